/**
 * Rewrites one student function for the fast (SES) engine: the source is parsed as ES5 with the
 * same parser and options as the reference engine (so both accept the same programs and report the
 * same syntax errors), then guards are spliced into the text:
 * - at every function entry and every loop iteration, `;if (($lb$s -= W) < 0) $lb$o();` takes W
 *   steps from the call's budget; W is the number of syntax nodes the guarded stretch of code holds,
 *   scaled to approximate JS-Interpreter's step count, so one budget means about the same in both;
 * - at the start of every `catch` block, `$lb$c(e);` rethrows a pending budget or depth failure, so
 *   student code cannot catch and ignore it;
 * - a read of a name declared nowhere becomes `$lb$u("name")`, which throws the ReferenceError
 *   JS-Interpreter throws (a compartment would quietly give undefined).
 * It also removes what SES refuses to evaluate (comments, `eval(` and HTML-comment-like text).
 */
import Interpreter from 'js-interpreter';
import { BOUND_NAMES, RESERVED_PREFIX } from './ses-names';
import { CompileError } from './types';
import type { CompiledFunction } from './types';

/**
 * Interpreter steps per syntax node, measured on typical generated code (loops over grids, calls
 * of helpers, arithmetic): JS-Interpreter takes two to three steps per node it evaluates.
 */
const STEPS_PER_NODE = 2;

interface AstNode {
  readonly type: string;
  readonly start: number;
  readonly end: number;
  readonly [field: string]: unknown;
}

interface Acorn {
  parse(code: string, options: Record<string, unknown>): AstNode;
}

/** A stretch of code one guard pays for. */
interface Region {
  nodes: number;
}

interface Splice {
  readonly at: number;
  /** Text to remove from `at` (0 for an insertion). */
  readonly remove: number;
  readonly text: string | (() => string);
}

/** The instrumented function, ready to be wrapped in the engine's compartment source. */
export interface InstrumentedFunction {
  /** The function's declaration, instrumented: `function NAME(...) { ... }`. */
  readonly code: string;
  /** The name the source declares (the function to call). */
  readonly declared: string;
}

const parserOptions = (sourceFile: string, onComment: (block: boolean, text: string, start: number, end: number) => void) => ({
  ...(Interpreter as unknown as { PARSE_OPTIONS: Record<string, unknown> }).PARSE_OPTIONS,
  sourceFile,
  onComment,
});

/** Parses and instruments one function; throws CompileError for code that cannot run. */
export function instrument(fn: CompiledFunction): InstrumentedFunction {
  const acorn = (Interpreter as unknown as { nativeGlobal: { acorn: Acorn } }).nativeGlobal.acorn;
  const comments: [number, number][] = [];
  let program: AstNode;
  try {
    program = acorn.parse(fn.source, parserOptions(fn.name, (_b, _t, start, end) => comments.push([start, end])));
  } catch (e) {
    const text = e instanceof Error ? e.message.replace(/\s*\((\d+):(\d+)\)$/, ' (line $1, column $2)') : String(e);
    throw new CompileError(fn.name, fn.layer, `its code has a syntax error: ${text}.`);
  }
  const body = program.body as AstNode[];
  const decls = body.filter((n) => n.type === 'FunctionDeclaration');
  const decl = decls.find((n) => (n.id as AstNode & { name: string } | null)?.name === fn.name) ?? decls[0];
  const declared = (decl?.id as { name?: string } | null | undefined)?.name;
  if (!decl || !declared) throw new CompileError(fn.name, fn.layer, 'its code is not a function declaration.');

  const splices: Splice[] = [];
  // The program's own declarations are visible to each other (recursion by name).
  const walker = new Walker(fn, splices, new Set(decls.map((d) => (d.id as { name: string }).name)));
  // Only declarations count, as in the reference engine (which declares a program but never runs
  // its statements): other top-level statements (from a text body with unbalanced braces) go.
  for (const s of body) {
    if (s.type === 'FunctionDeclaration') walker.visit(s, { nodes: 0 });
    else splices.push({ at: s.start, remove: s.end - s.start, text: '' });
  }
  for (const [start, end] of comments) splices.push({ at: start, remove: end - start, text: blank(fn.source.slice(start, end)) });
  const code = apply(fn.source, splices);
  const refused = sesRefusal(code);
  if (refused) throw new CompileError(fn.name, fn.layer, `its code contains "${refused}", which the fast engine cannot run; write it differently.`);
  return { code, declared };
}

/** Walks the tree, counting nodes into regions and recording the splices. */
class Walker {
  /** Names declared by each enclosing function, innermost last. */
  private readonly scopes: Set<string>[];
  /** Identifiers that are not reads of a variable (declarations, property names, labels, write targets). */
  private readonly notRead = new WeakSet<AstNode>();

  constructor(
    private readonly fn: CompiledFunction,
    private readonly splices: Splice[],
    program: Set<string>,
  ) {
    this.scopes = [program];
  }

  visit(node: AstNode, region: Region): void {
    region.nodes++;
    this.markNotRead(node);
    switch (node.type) {
      case 'FunctionDeclaration':
      case 'FunctionExpression':
        return this.functionNode(node);
      case 'ForStatement':
        return this.loop(node, region, ['init'], ['test', 'update']);
      case 'WhileStatement':
      case 'DoWhileStatement':
        return this.loop(node, region, [], ['test']);
      case 'ForInStatement':
        return this.loop(node, region, ['left', 'right'], []);
      case 'CatchClause': {
        const param = node.param as AstNode & { name: string };
        const block = node.body as AstNode;
        this.splices.push({ at: block.start + 1, remove: 0, text: `${RESERVED_PREFIX}c(${param.name});` });
        break;
      }
      case 'Identifier':
        this.identifier(node as AstNode & { name: string });
        return;
      case 'Literal':
        this.literal(node as AstNode & { raw: string; value: unknown; regex?: unknown });
        return;
      case 'IfStatement':
      case 'ConditionalExpression':
        return this.branches(node, region);
      case 'BinaryExpression':
        this.htmlCommentLike(node);
        break;
    }
    this.children(node, region);
  }

  private children(node: AstNode, region: Region): void {
    for (const key of Object.keys(node)) {
      if (key === 'type' || key === 'loc' || key === 'start' || key === 'end') continue;
      const v = node[key];
      if (Array.isArray(v)) {
        for (const x of v) if (isNode(x)) this.visit(x, region);
      } else if (isNode(v)) this.visit(v, region);
    }
  }

  /** Identifiers under `node` that name no variable to read. */
  private markNotRead(node: AstNode): void {
    const mark = (v: unknown): void => {
      if (isNode(v) && v.type === 'Identifier') this.notRead.add(v);
    };
    switch (node.type) {
      case 'MemberExpression':
        if (!node.computed) mark(node.property);
        break;
      case 'Property':
        mark(node.key);
        break;
      case 'LabeledStatement':
      case 'BreakStatement':
      case 'ContinueStatement':
        mark(node.label);
        break;
      case 'VariableDeclarator':
        mark(node.id);
        break;
      case 'FunctionDeclaration':
      case 'FunctionExpression':
        mark(node.id);
        (node.params as AstNode[]).forEach(mark);
        break;
      case 'CatchClause':
        mark(node.param);
        break;
      // Writes: SES throws the ReferenceError itself when the name is declared nowhere.
      case 'AssignmentExpression':
        mark(node.left);
        break;
      case 'UpdateExpression':
        mark(node.argument);
        break;
      case 'ForInStatement':
        mark(node.left);
        break;
      // `typeof x` of an undeclared x is "undefined", not an error.
      case 'UnaryExpression':
        if (node.operator === 'typeof') mark(node.argument);
        break;
    }
  }

  private functionNode(node: AstNode): void {
    const region: Region = { nodes: 0 };
    const block = node.body as AstNode;
    const statements = block.body as AstNode[];
    // After the directive prologue: a guard before 'use strict' would turn strict mode off.
    let at = block.start + 1;
    for (const s of statements) {
      const e = s.expression as (AstNode & { value?: unknown }) | undefined;
      if (s.type !== 'ExpressionStatement' || e?.type !== 'Literal' || typeof e.value !== 'string') break;
      at = s.end;
    }
    this.splices.push({ at, remove: 0, text: () => guard(region) });
    if (node.id) this.visit(node.id as AstNode, region);
    this.scopes.push(declaredIn(node));
    for (const p of node.params as AstNode[]) this.visit(p, region);
    for (const s of statements) this.visit(s, region);
    this.scopes.pop();
  }

  /** Only one branch runs: the stretch pays for the larger one, as the interpreter would at worst. */
  private branches(node: AstNode, region: Region): void {
    this.visit(node.test as AstNode, region);
    let most = 0;
    for (const key of ['consequent', 'alternate']) {
      const branch = node[key];
      if (!isNode(branch)) continue;
      const r: Region = { nodes: 0 };
      this.visit(branch, r);
      most = Math.max(most, r.nodes);
    }
    region.nodes += most;
  }

  private loop(node: AstNode, outer: Region, once: readonly string[], each: readonly string[]): void {
    const region: Region = { nodes: 0 };
    for (const key of once) if (isNode(node[key])) this.visit(node[key], outer);
    for (const key of each) if (isNode(node[key])) this.visit(node[key], region);
    const body = node.body as AstNode;
    if (body.type === 'BlockStatement') {
      this.splices.push({ at: body.start + 1, remove: 0, text: () => guard(region) });
      region.nodes++;
      this.children(body, region);
    } else {
      this.splices.push({ at: body.start, remove: 0, text: () => `{${guard(region)}` });
      this.visit(body, region);
      this.splices.push({ at: body.end, remove: 0, text: '}' });
    }
  }

  private identifier(node: AstNode & { name: string }): void {
    const name = node.name;
    if (name.startsWith(RESERVED_PREFIX)) {
      throw new CompileError(this.fn.name, this.fn.layer, `the name "${name}" is reserved: names may not start with "${RESERVED_PREFIX}".`);
    }
    if (this.notRead.has(node)) return;
    if (this.scopes.some((s) => s.has(name))) return;
    // SES refuses anything that looks like a direct eval; `eval` is not available anyway.
    if (name === 'eval') this.splices.push({ at: node.start, remove: node.end - node.start, text: `${RESERVED_PREFIX}ev` });
    else if (!BOUND_NAMES.has(name)) this.splices.push({ at: node.start, remove: node.end - node.start, text: `${RESERVED_PREFIX}u(${JSON.stringify(name)})` });
  }

  private literal(node: AstNode & { raw: string; value: unknown; regex?: unknown }): void {
    if (!sesRefusal(node.raw)) return;
    let text: string;
    if (typeof node.value === 'string') text = safeString(node.value);
    else if (node.value instanceof RegExp) text = `new RegExp(${safeString(node.value.source)}, ${JSON.stringify(node.value.flags)})`;
    else return;
    this.splices.push({ at: node.start, remove: node.end - node.start, text });
  }

  /** `a-->b` and `a<!--b` are valid ES5 that SES reads as HTML comments: add a space. */
  private htmlCommentLike(node: AstNode): void {
    const left = node.left as AstNode;
    const right = node.right as AstNode;
    if (node.operator === '>' && left.type === 'UpdateExpression' && left.operator === '--' && left.prefix === false) {
      this.splices.push({ at: left.end, remove: 0, text: ' ' });
    }
    const arg = right.argument as AstNode | undefined;
    if (node.operator === '<' && right.type === 'UnaryExpression' && right.operator === '!' && arg?.type === 'UpdateExpression' && arg.operator === '--' && arg.prefix === true) {
      this.splices.push({ at: arg.start, remove: 0, text: ' ' });
    }
  }
}

/**
 * The names a function declares (ES5 scoping: parameters, `var`s and function declarations
 * anywhere in its body outside nested functions, catch parameters, `arguments`, its own name).
 */
function declaredIn(fn: AstNode): Set<string> {
  const names = new Set<string>(['arguments']);
  const id = fn.id as { name: string } | null;
  if (id && fn.type === 'FunctionExpression') names.add(id.name);
  for (const p of fn.params as { name: string }[]) names.add(p.name);
  const walk = (node: AstNode): void => {
    switch (node.type) {
      case 'FunctionDeclaration':
        names.add((node.id as { name: string }).name);
        return;
      case 'FunctionExpression':
        return;
      case 'VariableDeclarator':
        names.add((node.id as { name: string }).name);
        break;
      case 'CatchClause':
        names.add((node.param as { name: string }).name);
        break;
    }
    for (const key of Object.keys(node)) {
      const v = node[key];
      if (Array.isArray(v)) {
        for (const x of v) if (isNode(x)) walk(x);
      } else if (isNode(v)) walk(v);
    }
  };
  for (const s of (fn.body as AstNode).body as AstNode[]) walk(s);
  return names;
}

function guard(region: Region): string {
  return `;if ((${RESERVED_PREFIX}s -= ${Math.max(1, region.nodes * STEPS_PER_NODE)}) < 0) ${RESERVED_PREFIX}o();`;
}

function isNode(v: unknown): v is AstNode {
  return typeof v === 'object' && v !== null && typeof (v as { type?: unknown }).type === 'string' && typeof (v as { start?: unknown }).start === 'number';
}

/** Applies the splices in order of position; at one position, in the order they were recorded. */
function apply(source: string, splices: readonly Splice[]): string {
  const sorted = splices.map((s, i) => ({ s, i })).sort((a, b) => a.s.at - b.s.at || a.i - b.i);
  let out = '';
  let pos = 0;
  for (const { s } of sorted) {
    if (s.at < pos) continue; // inside a stretch already replaced (a comment or literal)
    out += source.slice(pos, s.at) + (typeof s.text === 'string' ? s.text : s.text());
    pos = s.at + s.remove;
  }
  return out + source.slice(pos);
}

/** A comment's text as spaces, keeping its line breaks (they matter to semicolon insertion). */
function blank(text: string): string {
  return text.replace(/[^\n\r\u2028\u2029]/g, ' ');
}

/** A string literal whose text cannot look like `eval(`, `import(` or an HTML comment to SES. */
function safeString(value: string): string {
  return JSON.stringify(value).replace(/[()<>\-\u2028\u2029]/g, (c) => `\\u${c.charCodeAt(0).toString(16).padStart(4, '0')}`);
}

// The patterns SES 2.3 rejects in evaluated source (ses/src/transforms.js).
const SES_PATTERNS: readonly [RegExp, string][] = [
  [/<!--|-->/, 'an HTML comment marker'],
  [/(^|[^.]|\.\.\.)\bimport(\s*(?:\(|\/[/*]))/, 'import('],
  [/(^|[^.])\beval(\s*\()/, 'eval('],
];

function sesRefusal(code: string): string | null {
  for (const [pattern, what] of SES_PATTERNS) if (pattern.test(code)) return what;
  return null;
}
