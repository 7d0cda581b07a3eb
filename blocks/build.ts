/**
 * Builds function bodies as block JSON from code: a small vocabulary for the example controllers,
 * tests and the app's "new function" template. Block ids are deterministic (`prefix.1`,
 * `prefix.2`...), so generated code and golden files are stable.
 *
 * This file has no side effects.
 */
import type { JsonValue } from '../app/core/values';
import { apiBlockType, apiInputName } from './domain/api-blocks';
import { API } from '../app/core/sandbox/api';
import type { ApiName } from '../app/core/sandbox/api';

/** A block state in Blockly's JSON serialization. */
export interface BlockState {
  type: string;
  id: string;
  fields?: Record<string, JsonValue>;
  inputs?: Record<string, { block: BlockState }>;
  next?: { block: BlockState };
  extraState?: JsonValue;
  inline?: boolean;
}

export type Statements = readonly BlockState[];

/** The body of a function with no blocks yet but its root (what the app creates). */
export function emptyBody(prefix = 'f'): JsonValue {
  return new BodyBuilder(prefix).body([], null);
}

export class BodyBuilder {
  private n = 0;
  private readonly variables = new Map<string, string>();

  constructor(private readonly prefix: string) {}

  private block(type: string, fields?: Record<string, JsonValue>, inputs?: Record<string, BlockState | null | undefined>): BlockState {
    const state: BlockState = { type, id: `${this.prefix}.${++this.n}` };
    if (fields) state.fields = fields;
    const ins = Object.entries(inputs ?? {}).filter((e): e is [string, BlockState] => !!e[1]);
    if (ins.length) state.inputs = Object.fromEntries(ins.map(([k, b]) => [k, { block: b }]));
    return state;
  }

  private chain(statements: Statements): BlockState | null {
    for (let i = statements.length - 2; i >= 0; i--) statements[i].next = { block: statements[i + 1] };
    return statements[0] ?? null;
  }

  private variable(name: string): { id: string } {
    let id = this.variables.get(name);
    if (!id) {
      id = `${this.prefix}.var.${name}`;
      this.variables.set(name, id);
    }
    return { id };
  }

  /** The whole body: a workspace holding the `lb_function` root block. */
  body(statements: Statements, result: BlockState | null): JsonValue {
    const root = this.block('lb_function', undefined, { DO: this.chain(statements), RETURN: result });
    const state: Record<string, JsonValue> = { blocks: { languageVersion: 0, blocks: [{ ...root, x: 20, y: 20 } as unknown as JsonValue] } };
    if (this.variables.size) state.variables = [...this.variables].map(([name, id]) => ({ name, id }));
    return JSON.parse(JSON.stringify(state)) as JsonValue;
  }

  // Names
  input(name: string) { return this.block('lb_input', { NAME: name }); }
  layerVar(name: string) { return this.block('lb_layer_variable', { NAME: name }); }
  get(name: string) { return this.block('variables_get', { VAR: this.variable(name) }); }
  set(name: string, value: BlockState) { return this.block('variables_set', { VAR: this.variable(name) }, { VALUE: value }); }
  change(name: string, delta: BlockState) { return this.block('math_change', { VAR: this.variable(name) }, { DELTA: delta }); }

  // Values
  num(n: number) { return this.block('math_number', { NUM: n }); }
  str(s: string) { return this.block('text', { TEXT: s }); }
  bool(b: boolean) { return this.block('logic_boolean', { BOOL: b ? 'TRUE' : 'FALSE' }); }
  nul() { return this.block('logic_null'); }
  constant(c: 'PI' | 'E' | 'INFINITY') { return this.block('math_constant', { CONSTANT: c }); }

  // Logic
  compare(op: 'EQ' | 'NEQ' | 'LT' | 'LTE' | 'GT' | 'GTE', a: BlockState, b: BlockState) { return this.block('logic_compare', { OP: op }, { A: a, B: b }); }
  and(a: BlockState, b: BlockState) { return this.block('logic_operation', { OP: 'AND' }, { A: a, B: b }); }
  or(a: BlockState, b: BlockState) { return this.block('logic_operation', { OP: 'OR' }, { A: a, B: b }); }
  not(a: BlockState) { return this.block('logic_negate', undefined, { BOOL: a }); }
  ternary(c: BlockState, a: BlockState, b: BlockState) { return this.block('logic_ternary', undefined, { IF: c, THEN: a, ELSE: b }); }
  /** if / else if ... / else. */
  if(branches: readonly [BlockState, Statements][], otherwise?: Statements) {
    const inputs: Record<string, BlockState | null> = {};
    branches.forEach(([cond, body], i) => {
      inputs[`IF${i}`] = cond;
      inputs[`DO${i}`] = this.chain(body);
    });
    if (otherwise) inputs.ELSE = this.chain(otherwise);
    const state = this.block('controls_if', undefined, inputs);
    if (branches.length > 1 || otherwise) state.extraState = { ...(branches.length > 1 ? { elseIfCount: branches.length - 1 } : {}), ...(otherwise ? { hasElse: true } : {}) };
    return state;
  }
  ret(value: BlockState) { return this.block('lb_return', undefined, { VALUE: value }); }

  // Loops
  forRange(name: string, from: BlockState, to: BlockState, by: BlockState, body: Statements) {
    return this.block('controls_for', { VAR: this.variable(name) }, { FROM: from, TO: to, BY: by, DO: this.chain(body) });
  }
  forEach(name: string, list: BlockState, body: Statements) { return this.block('controls_forEach', { VAR: this.variable(name) }, { LIST: list, DO: this.chain(body) }); }
  whileTrue(cond: BlockState, body: Statements) { return this.block('controls_whileUntil', { MODE: 'WHILE' }, { BOOL: cond, DO: this.chain(body) }); }
  flow(kind: 'BREAK' | 'CONTINUE') { return this.block('controls_flow_statements', { FLOW: kind }); }

  // Math
  arith(op: 'ADD' | 'MINUS' | 'MULTIPLY' | 'DIVIDE' | 'POWER', a: BlockState, b: BlockState) { return this.block('math_arithmetic', { OP: op }, { A: a, B: b }); }
  single(op: 'ROOT' | 'ABS' | 'NEG' | 'LN' | 'LOG10' | 'EXP' | 'POW10', x: BlockState) { return this.block('math_single', { OP: op }, { NUM: x }); }
  trig(op: 'SIN' | 'COS' | 'TAN' | 'ASIN' | 'ACOS' | 'ATAN', x: BlockState) { return this.block('math_trig', { OP: op }, { NUM: x }); }
  modulo(a: BlockState, b: BlockState) { return this.block('math_modulo', undefined, { DIVIDEND: a, DIVISOR: b }); }
  max(list: BlockState) { return this.block('math_on_list', { OP: 'MAX' }, { LIST: list }); }

  // Text
  print(x: BlockState) { return this.block('text_print', undefined, { TEXT: x }); }
  join(...parts: BlockState[]) { return this.withExtra(this.block('text_join', undefined, Object.fromEntries(parts.map((p, i) => [`ADD${i}`, p]))), { itemCount: parts.length }); }

  // Lists
  list(...items: BlockState[]) { return this.withExtra(this.block('lists_create_with', undefined, Object.fromEntries(items.map((p, i) => [`ADD${i}`, p]))), { itemCount: items.length }); }
  length(list: BlockState) { return this.block('lists_length', undefined, { VALUE: list }); }
  isEmpty(list: BlockState) { return this.block('lists_isEmpty', undefined, { VALUE: list }); }
  /** Item number `at` (counting from 1, as Blockly's list blocks do). */
  item(list: BlockState, at: BlockState) { return this.block('lists_getIndex', { MODE: 'GET', WHERE: 'FROM_START' }, { VALUE: list, AT: at }); }
  first(list: BlockState) { return this.block('lists_getIndex', { MODE: 'GET', WHERE: 'FIRST' }, { VALUE: list }); }
  /** The list from item number `from` (counting from 1) to the end. */
  restFrom(list: BlockState, from: BlockState) {
    return this.block('lists_getSublist', { WHERE1: 'FROM_START', WHERE2: 'LAST' }, { LIST: list, AT1: from });
  }

  // Layerbot's domain blocks
  api(name: ApiName, ...args: BlockState[]) {
    const params = API[name].params;
    return this.block(apiBlockType(name), undefined, Object.fromEntries(params.map((p, i) => [apiInputName(p.name), args[i]])));
  }
  point(x: BlockState, y: BlockState) { return this.block('lb_point', undefined, { X: x, Y: y }); }
  pointPart(part: 'X' | 'Y', p: BlockState) { return this.block('lb_point_part', { PART: part }, { POINT: p }); }
  move(heading: BlockState, dx: BlockState, dy: BlockState) { return this.block('lb_move', undefined, { HEADING: heading, DX: dx, DY: dy }); }
  cell(col: BlockState, row: BlockState) { return this.block('lb_cell', undefined, { COL: col, ROW: row }); }
  cellPart(part: 'COL' | 'ROW', c: BlockState) { return this.block('lb_cell_part', { PART: part }, { CELL: c }); }
  tableGet(table: BlockState, col: BlockState, row: BlockState) { return this.block('lb_table_get', undefined, { TABLE: table, COL: col, ROW: row }); }
  tableSet(table: BlockState, col: BlockState, row: BlockState, value: BlockState) { return this.block('lb_table_set', undefined, { TABLE: table, COL: col, ROW: row, VALUE: value }); }
  gridSize(part: 'cols' | 'rows' | 'cell', grid: BlockState) { return this.block('lb_grid_size', { PART: part }, { GRID: grid }); }
  forEachCell(grid: BlockState, col: string, row: string, body: Statements) {
    return this.block('lb_for_each_cell', { COL: this.variable(col), ROW: this.variable(row) }, { GRID: grid, DO: this.chain(body) });
  }
  action(a: 0 | 1 | 2 | 3 | 4) { return this.block('lb_action', { ACTION: String(a) }); }

  private withExtra(state: BlockState, extra: JsonValue): BlockState {
    state.extraState = extra;
    return state;
  }
}
