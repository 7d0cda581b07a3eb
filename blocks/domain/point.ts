/**
 * Readable blocks for points and the body command: make a point, take its x or y, make a move
 * {heading, dx, dy}. They generate plain expressions (no native call).
 *
 * This file has no side effects.
 */
import { Order } from 'blockly/javascript';
import type { BlockFamily } from '../types';
import { COLOURS } from '../types';

export const POINT_BLOCK = 'lb_point';
export const POINT_PART_BLOCK = 'lb_point_part';
export const MOVE_BLOCK = 'lb_move';

export const pointBlocks: BlockFamily = {
  definitions: [
    {
      type: POINT_BLOCK,
      message0: 'point x %1 y %2',
      args0: [
        { type: 'input_value', name: 'X', check: 'Number' },
        { type: 'input_value', name: 'Y', check: 'Number' },
      ],
      inputsInline: true,
      output: 'Array',
      colour: COLOURS.geometry,
      tooltip: 'A point [x, y].',
    },
    {
      type: POINT_PART_BLOCK,
      message0: '%1 of point %2',
      args0: [
        { type: 'field_dropdown', name: 'PART', options: [['x', 'X'], ['y', 'Y']] },
        { type: 'input_value', name: 'POINT', check: 'Array' },
      ],
      inputsInline: true,
      output: 'Number',
      colour: COLOURS.geometry,
      tooltip: 'The x (first) or y (second) coordinate of a point [x, y].',
    },
    {
      type: MOVE_BLOCK,
      message0: 'move: heading %1 dx %2 dy %3',
      args0: [
        { type: 'input_value', name: 'HEADING', check: 'Number' },
        { type: 'input_value', name: 'DX', check: 'Number' },
        { type: 'input_value', name: 'DY', check: 'Number' },
      ],
      output: null,
      colour: COLOURS.world,
      tooltip: 'The body command: the new heading in degrees and the change of position (dx, dy). The body moves at most 1 unit per tick.',
    },
  ],
  generators: {
    [POINT_BLOCK]: (block, gen) => [`[${gen.valueToCode(block, 'X', Order.NONE) || '0'}, ${gen.valueToCode(block, 'Y', Order.NONE) || '0'}]`, Order.ATOMIC],
    [POINT_PART_BLOCK]: (block, gen) => {
      const point = gen.requiredValue(block, 'POINT', Order.MEMBER, 'of point');
      return [`${point}[${block.getFieldValue('PART') === 'Y' ? 1 : 0}]`, Order.MEMBER];
    },
    [MOVE_BLOCK]: (block, gen) => {
      const v = (name: string) => gen.requiredValue(block, name, Order.NONE, 'move');
      return [`{heading: ${v('HEADING')}, dx: ${v('DX')}, dy: ${v('DY')}}`, Order.ATOMIC];
    },
  },
};
