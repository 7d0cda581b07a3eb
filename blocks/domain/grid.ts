/**
 * Readable blocks for grids and tables (a table is a list of rows, each a list of columns, as
 * `newGrid` makes it): cells [column, row] counted from 0, reading and writing a table at a cell,
 * a grid's size, a loop over every cell, and the grid actions (north, east, south, west, stay).
 * They generate plain expressions and loops, so value iteration runs without native calls in its
 * inner loops.
 *
 * This file has no side effects.
 */
import * as Blockly from 'blockly/core';
import { Order } from 'blockly/javascript';
import type { BlockFamily } from '../types';
import { COLOURS } from '../types';

export const CELL_BLOCK = 'lb_cell';
export const CELL_PART_BLOCK = 'lb_cell_part';
export const TABLE_GET_BLOCK = 'lb_table_get';
export const TABLE_SET_BLOCK = 'lb_table_set';
export const GRID_SIZE_BLOCK = 'lb_grid_size';
export const FOR_EACH_CELL_BLOCK = 'lb_for_each_cell';
export const ACTION_BLOCK = 'lb_action';

/** The grid actions, numbered as in the original design. */
export const ACTIONS = [
  ['north ↑', '0'],
  ['east →', '1'],
  ['south ↓', '2'],
  ['west ←', '3'],
  ['stay', '4'],
] as const;

export const gridBlocks: BlockFamily = {
  definitions: [
    {
      type: CELL_BLOCK,
      message0: 'cell column %1 row %2',
      args0: [
        { type: 'input_value', name: 'COL', check: 'Number' },
        { type: 'input_value', name: 'ROW', check: 'Number' },
      ],
      inputsInline: true,
      output: 'Array',
      colour: COLOURS.grid,
      tooltip: 'A grid cell [column, row]; columns and rows are counted from 0.',
    },
    {
      type: CELL_PART_BLOCK,
      message0: '%1 of cell %2',
      args0: [
        { type: 'field_dropdown', name: 'PART', options: [['column', 'COL'], ['row', 'ROW']] },
        { type: 'input_value', name: 'CELL', check: 'Array' },
      ],
      inputsInline: true,
      output: 'Number',
      colour: COLOURS.grid,
      tooltip: 'The column (first) or row (second) of a cell [column, row].',
    },
    {
      type: TABLE_GET_BLOCK,
      message0: 'in table %1 at column %2 row %3',
      args0: [
        { type: 'input_value', name: 'TABLE', check: 'Array' },
        { type: 'input_value', name: 'COL', check: 'Number' },
        { type: 'input_value', name: 'ROW', check: 'Number' },
      ],
      inputsInline: true,
      output: null,
      colour: COLOURS.grid,
      tooltip: 'The entry of a table (one entry per grid cell) at a column and a row, counted from 0.',
    },
    {
      type: TABLE_SET_BLOCK,
      message0: 'in table %1 at column %2 row %3 set %4',
      args0: [
        { type: 'input_value', name: 'TABLE', check: 'Array' },
        { type: 'input_value', name: 'COL', check: 'Number' },
        { type: 'input_value', name: 'ROW', check: 'Number' },
        { type: 'input_value', name: 'VALUE' },
      ],
      inputsInline: true,
      previousStatement: null,
      nextStatement: null,
      colour: COLOURS.grid,
      tooltip: 'Changes the entry of a table at a column and a row (counted from 0). Only tables the function made itself can be changed.',
    },
    {
      type: GRID_SIZE_BLOCK,
      message0: '%1 of grid %2',
      args0: [
        { type: 'field_dropdown', name: 'PART', options: [['columns', 'cols'], ['rows', 'rows'], ['cell size', 'cell']] },
        { type: 'input_value', name: 'GRID' },
      ],
      inputsInline: true,
      output: 'Number',
      colour: COLOURS.grid,
      tooltip: 'The number of columns or rows of a grid, or the size of its cells.',
    },
    {
      type: FOR_EACH_CELL_BLOCK,
      message0: 'for each cell of grid %1 column %2 row %3',
      args0: [
        { type: 'input_value', name: 'GRID' },
        { type: 'field_variable', name: 'COL', variable: 'column' },
        { type: 'field_variable', name: 'ROW', variable: 'row' },
      ],
      message1: 'do %1',
      args1: [{ type: 'input_statement', name: 'DO' }],
      previousStatement: null,
      nextStatement: null,
      colour: COLOURS.grid,
      tooltip: 'Runs the blocks inside once for every cell of the grid, row by row from row 0, setting the column and row variables.',
    },
    {
      type: ACTION_BLOCK,
      message0: 'action %1',
      args0: [{ type: 'field_dropdown', name: 'ACTION', options: ACTIONS.map(([l, v]) => [l, v]) }],
      output: 'Number',
      colour: COLOURS.grid,
      tooltip: 'A grid action as a number: north 0, east 1, south 2, west 3, stay 4.',
    },
  ],
  generators: {
    [CELL_BLOCK]: (block, gen) => [`[${gen.valueToCode(block, 'COL', Order.NONE) || '0'}, ${gen.valueToCode(block, 'ROW', Order.NONE) || '0'}]`, Order.ATOMIC],
    [CELL_PART_BLOCK]: (block, gen) => [`${gen.requiredValue(block, 'CELL', Order.MEMBER, 'of cell')}[${block.getFieldValue('PART') === 'ROW' ? 1 : 0}]`, Order.MEMBER],
    [TABLE_GET_BLOCK]: (block, gen) => {
      const v = (n: string, o: Order) => gen.requiredValue(block, n, o, 'in table');
      return [`${v('TABLE', Order.MEMBER)}[${v('ROW', Order.NONE)}][${v('COL', Order.NONE)}]`, Order.MEMBER];
    },
    [TABLE_SET_BLOCK]: (block, gen) => {
      const v = (n: string, o: Order) => gen.requiredValue(block, n, o, 'in table ... set');
      return `${v('TABLE', Order.MEMBER)}[${v('ROW', Order.NONE)}][${v('COL', Order.NONE)}] = ${v('VALUE', Order.ASSIGNMENT)};\n`;
    },
    [GRID_SIZE_BLOCK]: (block, gen) => [`${gen.requiredValue(block, 'GRID', Order.MEMBER, 'of grid')}.${String(block.getFieldValue('PART'))}`, Order.MEMBER],
    [FOR_EACH_CELL_BLOCK]: (block, gen) => {
      let grid = gen.requiredValue(block, 'GRID', Order.MEMBER, 'for each cell');
      const col = gen.getVariableName(block.getFieldValue('COL') as string);
      const row = gen.getVariableName(block.getFieldValue('ROW') as string);
      let setup = '';
      if (!/^\w+$/.test(grid)) {
        const temp = gen.nameDB_!.getDistinctName('grid', Blockly.Names.NameType.VARIABLE);
        setup = `var ${temp} = ${grid};\n`;
        grid = temp;
      }
      const body = gen.addLoopTrap(gen.statementToCode(block, 'DO'), block);
      const inner = `for (${col} = 0; ${col} < ${grid}.cols; ${col}++) {\n${body}}\n`;
      return `${setup}for (${row} = 0; ${row} < ${grid}.rows; ${row}++) {\n${gen.prefixLines(inner, gen.INDENT)}}\n`;
    },
    [ACTION_BLOCK]: (block) => [String(Number(block.getFieldValue('ACTION'))), Order.ATOMIC],
  },
};
