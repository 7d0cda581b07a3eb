/**
 * `lb_input` reads one of the function's inputs (an arc) and `lb_layer_variable` one of its
 * layer's variables, by their plain names: the engine declares both in the function.
 *
 * This file has no side effects.
 */
import type * as Blockly from 'blockly/core';
import { Order } from 'blockly/javascript';
import { getFunctionContext } from '../context';
import { FIELD_NAME_DROPDOWN } from '../fields/name-dropdown';
import type { BlockFamily, BlockGenerator } from '../types';
import { BlocksError, COLOURS } from '../types';

export const INPUT_BLOCK = 'lb_input';
export const LAYER_VARIABLE_BLOCK = 'lb_layer_variable';

function nameReader(kind: 'inputs' | 'variables', what: string): BlockGenerator {
  return (block: Blockly.Block) => {
    const name = String(block.getFieldValue('NAME') ?? '');
    const context = getFunctionContext(block.workspace);
    if (!name) throw new BlocksError(`A "${what}" block has no name chosen: pick one from its list.`, block.id);
    if (context && !context[kind].includes(name)) {
      const known = context[kind].length ? `It has: ${context[kind].join(', ')}.` : `It has none.`;
      const owner = kind === 'inputs' ? `function "${context.name}"` : `layer of function "${context.name}"`;
      throw new BlocksError(`The "${what}" block reads "${name}", but the ${owner} has no ${what} with that name. ${known}`, block.id);
    }
    return [name, Order.ATOMIC];
  };
}

export const nameBlocks: BlockFamily = {
  definitions: [
    {
      type: INPUT_BLOCK,
      message0: 'input %1',
      args0: [{ type: FIELD_NAME_DROPDOWN, name: 'NAME', kind: 'inputs' }],
      output: null,
      colour: COLOURS.inputs,
      tooltip: "The value of one of this function's inputs (an arc from another function, the world or a random source).",
    },
    {
      type: LAYER_VARIABLE_BLOCK,
      message0: 'layer variable %1',
      args0: [{ type: FIELD_NAME_DROPDOWN, name: 'NAME', kind: 'variables' }],
      output: null,
      colour: COLOURS.inputs,
      tooltip: "The value of one of the layer's variables (a setting every function of the layer can read).",
    },
  ],
  generators: {
    [INPUT_BLOCK]: nameReader('inputs', 'input'),
    [LAYER_VARIABLE_BLOCK]: nameReader('variables', 'layer variable'),
  },
};
