/**
 * Controller-editor blocks for functions and arcs. `lb_controller_function` sits only inside a
 * layer: its name, declared output type and its inputs, each an `lb_arc` (parameter name and
 * source). The function's body (its blocks) and description travel with the block as extra state,
 * so moving or renaming a function keeps its body.
 *
 * Arc sources are written `function:NAME`, `previous:NAME`, `world:INPUT` or `random:NAME`.
 *
 * This file has no side effects.
 */
import * as Blockly from 'blockly/core';
import type { JsonValue } from '../../app/core/values';
import { VALUE_TYPES } from '../../app/core/values';
import { FIELD_NAME_DROPDOWN } from '../fields/name-dropdown';
import type { BlockFamily } from '../types';
import { COLOURS } from '../types';
import { CHECKS } from './layer';

export const CONTROLLER_FUNCTION_BLOCK = 'lb_controller_function';
export const ARC_BLOCK = 'lb_arc';

/** What a function block carries besides its fields. */
export interface FunctionExtraState {
  body?: { kind: 'blocks'; blocks: JsonValue } | { kind: 'text'; code: string };
  description?: string;
}

type WithExtra = Blockly.Block & { lbExtra?: FunctionExtraState };

/** The name of the function block's "open" button field (not saved: it is an image). */
export const OPEN_FIELD = 'OPEN';

/** A small "open" arrow (an SVG data URI, so it loads offline and under the page's CSP). */
const OPEN_ICON =
  'data:image/svg+xml;utf8,' +
  encodeURIComponent(
    '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 16 16"><circle cx="8" cy="8" r="8" fill="white" fill-opacity="0.92"/>' +
      '<path d="M6.5 4.5 10 8l-3.5 3.5" fill="none" stroke="#1c2333" stroke-width="1.9" stroke-linecap="round" stroke-linejoin="round"/></svg>',
  );

let openHandler: ((block: Blockly.Block) => void) | null = null;

/** What a click on a function block's "open" button does (the controller editor sets it). */
export function setOpenFunctionHandler(handler: ((block: Blockly.Block) => void) | null): void {
  openHandler = handler;
}

export const functionBlocks: BlockFamily = {
  definitions: [
    {
      type: CONTROLLER_FUNCTION_BLOCK,
      message0: 'function %1 gives %2',
      args0: [
        { type: 'field_input', name: 'NAME', text: 'f' },
        { type: 'field_dropdown', name: 'OUTPUT', options: VALUE_TYPES.map((t) => [t, t]) },
      ],
      message1: 'inputs %1',
      args1: [{ type: 'input_statement', name: 'ARCS', check: CHECKS.arc }],
      previousStatement: CHECKS.function,
      nextStatement: CHECKS.function,
      colour: COLOURS.function,
      tooltip: 'A function: it takes its inputs (arcs) and gives one output each tick. Open it to edit its blocks.',
      mutator: 'lb_controller_function_state',
      extensions: ['lb_controller_function_open'],
    },
    {
      type: ARC_BLOCK,
      message0: '%1 from %2 %3',
      args0: [
        { type: 'field_input', name: 'NAME', text: 'input' },
        { type: FIELD_NAME_DROPDOWN, name: 'SOURCE', kind: 'arcSources' },
        { type: 'field_input', name: 'INITIAL', text: 'null' },
      ],
      previousStatement: CHECKS.arc,
      nextStatement: CHECKS.arc,
      colour: COLOURS.arc,
      tooltip: 'An input of the function: its name in the function and where its value comes from. For a previous-tick source, the last box holds the value on the first tick.',
      extensions: ['lb_arc_initial_visibility'],
    },
  ],
  extensions: {
    lb_controller_function_open(this: Blockly.Block) {
      // An "open" button at the start of the first row: the editor opens the function's blocks.
      const image = { type: 'field_image', src: OPEN_ICON, width: 16, height: 16, alt: 'open blocks' };
      const field = Blockly.fieldRegistry.fromJson(image) as Blockly.FieldImage | null;
      if (!field) return;
      field.setOnClickHandler((f) => {
        const block = f.getSourceBlock();
        if (block && openHandler) openHandler(block);
      });
      field.setTooltip('Open this function\'s blocks');
      this.inputList[0]?.insertFieldAt(0, field, OPEN_FIELD);
    },
    lb_arc_initial_visibility(this: Blockly.Block) {
      // The initial value matters only for previous-tick sources: show it only for them.
      const showInitial = (block: Blockly.Block, source: unknown) => block.getField('INITIAL')?.setVisible(String(source ?? '').startsWith('previous:'));
      const source = this.getField('SOURCE');
      source?.setValidator((value: string) => {
        const block = source.getSourceBlock();
        if (block) showInitial(block, value);
        return value;
      });
      showInitial(this, this.getFieldValue('SOURCE'));
    },
  },
  mutators: {
    lb_controller_function_state: {
      saveExtraState(this: WithExtra): FunctionExtraState | null {
        return this.lbExtra && Object.keys(this.lbExtra).length ? { ...this.lbExtra } : null;
      },
      loadExtraState(this: WithExtra, state: FunctionExtraState): void {
        this.lbExtra = { ...state };
      },
    },
  },
  generators: {},
};

/** The extra state (body, description) of a controller function block. */
export function functionExtra(block: Blockly.Block): FunctionExtraState {
  return (block as WithExtra).lbExtra ?? {};
}

export function setFunctionExtra(block: Blockly.Block, extra: FunctionExtraState): void {
  (block as WithExtra).lbExtra = { ...extra };
}
