/**
 * The toolboxes. `makeToolbox(categories?)` is the function-body toolbox; a challenge pack may
 * offer only some categories (by name, e.g. ["Inputs", "Logic", "Math"]). Blockly's unseeded
 * random blocks are left out: random values come from random-source inputs.
 * `makeControllerToolbox()` holds the controller editor's layer, function, arc and random blocks.
 *
 * This file has no side effects.
 */
import type * as Blockly from 'blockly/core';
import { apiBlocksOf } from './domain/api-blocks';
import { COLOURS } from './types';

type Item = Blockly.utils.toolbox.ToolboxItemInfo;

const block = (type: string, extra: Record<string, unknown> = {}): Item => ({ kind: 'block', type, ...extra }) as Item;
const num = (n: number) => ({ block: { type: 'math_number', fields: { NUM: n } } });
const shadowNum = (n: number) => ({ shadow: { type: 'math_number', fields: { NUM: n } } });

interface Category {
  readonly name: string;
  readonly colour: number;
  readonly contents?: readonly Item[];
  /** Blockly's dynamic categories ("VARIABLE", "PROCEDURE"). */
  readonly custom?: string;
}

/** Every function-body category, in toolbox order. */
export const CATEGORIES: readonly Category[] = [
  { name: 'Inputs', colour: COLOURS.inputs, contents: [block('lb_input'), block('lb_layer_variable'), block('lb_return')] },
  {
    name: 'Logic',
    colour: COLOURS.logic,
    contents: ['controls_if', 'logic_compare', 'logic_operation', 'logic_negate', 'logic_boolean', 'logic_null', 'logic_ternary'].map((t) => block(t)),
  },
  {
    name: 'Loops',
    colour: COLOURS.loops,
    contents: [
      block('controls_repeat_ext', { inputs: { TIMES: shadowNum(10) } }),
      block('controls_whileUntil'),
      block('controls_for', { inputs: { FROM: shadowNum(1), TO: shadowNum(10), BY: shadowNum(1) } }),
      block('controls_forEach'),
      block('controls_flow_statements'),
    ],
  },
  {
    name: 'Math',
    colour: COLOURS.math,
    contents: [
      block('math_number'),
      block('math_arithmetic', { inputs: { A: shadowNum(1), B: shadowNum(1) } }),
      block('math_single', { inputs: { NUM: shadowNum(9) } }),
      block('math_trig', { inputs: { NUM: shadowNum(45) } }),
      block('math_constant'),
      block('math_number_property', { inputs: { NUMBER_TO_CHECK: shadowNum(0) } }),
      block('math_round', { inputs: { NUM: shadowNum(3.1) } }),
      block('math_on_list'),
      block('math_modulo', { inputs: { DIVIDEND: shadowNum(64), DIVISOR: shadowNum(10) } }),
      block('math_constrain', { inputs: { VALUE: shadowNum(50), LOW: shadowNum(1), HIGH: shadowNum(100) } }),
      block('math_atan2', { inputs: { X: shadowNum(1), Y: shadowNum(1) } }),
    ],
  },
  {
    name: 'Text',
    colour: COLOURS.text,
    contents: ['text', 'text_join', 'text_append', 'text_length', 'text_isEmpty', 'text_indexOf', 'text_charAt', 'text_getSubstring', 'text_changeCase', 'text_trim', 'text_print'].map((t) => block(t)),
  },
  {
    name: 'Lists',
    colour: COLOURS.lists,
    contents: [
      block('lists_create_with', { extraState: { itemCount: 0 } }),
      block('lists_create_with'),
      block('lists_repeat', { inputs: { NUM: num(5) } }),
      ...['lists_length', 'lists_isEmpty', 'lists_indexOf', 'lists_getIndex', 'lists_setIndex', 'lists_getSublist', 'lists_split', 'lists_sort', 'lists_reverse'].map((t) => block(t)),
      ...apiBlocksOf('list').map((t) => block(t)),
    ],
  },
  {
    name: 'Geometry',
    colour: COLOURS.geometry,
    contents: [block('lb_point'), block('lb_point_part'), ...apiBlocksOf('geometry').map((t) => block(t))],
  },
  { name: 'World', colour: COLOURS.world, contents: [block('lb_move'), ...apiBlocksOf('world').map((t) => block(t))] },
  {
    name: 'Grid',
    colour: COLOURS.grid,
    contents: [
      ...apiBlocksOf('grid').map((t) => block(t)),
      ...['lb_cell', 'lb_cell_part', 'lb_table_get', 'lb_table_set', 'lb_grid_size', 'lb_for_each_cell', 'lb_action'].map((t) => block(t)),
    ],
  },
  { name: 'Variables', colour: COLOURS.variables, custom: 'VARIABLE' },
  { name: 'Helpers', colour: COLOURS.helpers, custom: 'PROCEDURE' },
];

export const CATEGORY_NAMES: readonly string[] = CATEGORIES.map((c) => c.name);

/** The function-body toolbox, optionally limited to some categories (unknown names are an error). */
export function makeToolbox(categories?: readonly string[]): Blockly.utils.toolbox.ToolboxDefinition {
  const unknown = (categories ?? []).filter((c) => !CATEGORY_NAMES.includes(c));
  if (unknown.length) throw new Error(`Unknown toolbox categories: ${unknown.join(', ')}. Known: ${CATEGORY_NAMES.join(', ')}.`);
  const chosen = categories ? CATEGORIES.filter((c) => categories.includes(c.name)) : CATEGORIES;
  return {
    kind: 'categoryToolbox',
    contents: chosen.map((c) => ({
      kind: 'category',
      name: c.name,
      colour: String(c.colour),
      ...(c.custom ? { custom: c.custom } : { contents: [...(c.contents ?? [])] }),
    })) as Blockly.utils.toolbox.ToolboxItemInfo[],
  };
}

/** The controller editor's toolbox: layers, functions, arcs, layer variables, random sources. */
export function makeControllerToolbox(): Blockly.utils.toolbox.ToolboxDefinition {
  return {
    kind: 'flyoutToolbox',
    contents: ['lb_layer', 'lb_controller_function', 'lb_arc', 'lb_layer_variable_def', 'lb_random_source'].map((t) => block(t)),
  };
}
