/**
 * `lb_return`: ends the function early with a value ("if the whisker touches, return left").
 *
 * This file has no side effects.
 */
import { Order } from 'blockly/javascript';
import type { BlockFamily } from '../types';
import { COLOURS } from '../types';

export const RETURN_BLOCK = 'lb_return';

export const returnBlock: BlockFamily = {
  definitions: [
    {
      type: RETURN_BLOCK,
      message0: 'return %1',
      args0: [{ type: 'input_value', name: 'VALUE' }],
      previousStatement: null,
      colour: COLOURS.function,
      tooltip: 'Stops the function here and gives this value as its output.',
    },
  ],
  generators: {
    [RETURN_BLOCK]: (block, generator) => `return ${generator.requiredValue(block, 'VALUE', Order.NONE, 'return')};\n`,
  },
};
