/**
 * `lb_function`: the root of a function's body. It shows the function's name and declared output
 * type (from the workspace's function context, not stored in the JSON), runs the blocks in DO,
 * then returns the value attached to RETURN.
 *
 * This file has no side effects.
 */
import { Order } from 'blockly/javascript';
import { VALUE_TYPE_LABELS } from '../../app/core/values';
import { getFunctionContext } from '../context';
import type { BlockFamily } from '../types';
import { BlocksError, COLOURS } from '../types';

export const FUNCTION_BLOCK = 'lb_function';

export const functionBlock: BlockFamily = {
  definitions: [
    {
      type: FUNCTION_BLOCK,
      message0: 'function %1 gives %2',
      args0: [
        { type: 'field_label', name: 'NAME', text: 'f' },
        { type: 'field_label', name: 'OUTPUT', text: 'any' },
      ],
      message1: 'do %1',
      args1: [{ type: 'input_statement', name: 'DO' }],
      message2: 'return %1',
      args2: [{ type: 'input_value', name: 'RETURN' }],
      colour: COLOURS.function,
      tooltip: 'The function: runs the blocks in "do", then gives the value attached to "return" as its output.',
      deletable: false,
      extensions: ['lb_function_init'],
    },
  ],
  extensions: {
    lb_function_init(this) {
      // The root block marks the return line itself in the debug code (see the generator).
      this.suppressPrefixSuffix = true;
    },
  },
  generators: {
    [FUNCTION_BLOCK]: (block, generator) => {
      const first = block.getInputTargetBlock('DO');
      const statements = first ? (generator.blockToCode(first) as string) : '';
      const value = generator.valueToCode(block, 'RETURN', Order.NONE);
      if (!value) {
        const output = getFunctionContext(block.workspace)?.output;
        const what = output ? VALUE_TYPE_LABELS[output] : 'its output';
        throw new BlocksError(`The function block's "return" socket is empty: attach the value the function gives (${what}).`, block.id);
      }
      const mark = generator.STATEMENT_PREFIX ? generator.injectId(generator.STATEMENT_PREFIX, block) : '';
      return `${statements}${mark}return ${value};\n`;
    },
  },
};
