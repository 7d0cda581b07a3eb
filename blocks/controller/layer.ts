/**
 * Controller-editor blocks for layers: `lb_layer` (a name, its variables, its random sources and
 * its functions; layers stack top to bottom), `lb_layer_variable_def` (a name and a value written
 * as JSON) and `lb_random_source` (a seeded random input).
 *
 * This file has no side effects.
 */
import { RANDOM_TYPES } from '../../app/core/controller/model';
import type { BlockFamily } from '../types';
import { COLOURS } from '../types';

export const LAYER_BLOCK = 'lb_layer';
export const LAYER_VARIABLE_DEF_BLOCK = 'lb_layer_variable_def';
export const RANDOM_SOURCE_BLOCK = 'lb_random_source';

/** Statement checks: what fits where in the controller workspace. */
export const CHECKS = { layer: 'lb_layer', function: 'lb_function', variable: 'lb_layer_variable', random: 'lb_random', arc: 'lb_arc' } as const;

export const layerBlocks: BlockFamily = {
  definitions: [
    {
      type: LAYER_BLOCK,
      message0: 'layer %1',
      args0: [{ type: 'field_input', name: 'NAME', text: 'Layer' }],
      message1: 'variables %1',
      args1: [{ type: 'input_statement', name: 'VARIABLES', check: CHECKS.variable }],
      message2: 'random inputs %1',
      args2: [{ type: 'input_statement', name: 'RANDOM', check: CHECKS.random }],
      message3: 'functions %1',
      args3: [{ type: 'input_statement', name: 'FUNCTIONS', check: CHECKS.function }],
      previousStatement: CHECKS.layer,
      nextStatement: CHECKS.layer,
      colour: COLOURS.layer,
      tooltip: 'A layer of the controller. Layers stack from the top (slow, symbolic decisions) to the bottom (fast reactions). Its variables are settings every function of the layer can read.',
    },
    {
      type: LAYER_VARIABLE_DEF_BLOCK,
      message0: '%1 = %2',
      args0: [
        { type: 'field_input', name: 'NAME', text: 'NAME' },
        { type: 'field_input', name: 'VALUE', text: '0' },
      ],
      previousStatement: CHECKS.variable,
      nextStatement: CHECKS.variable,
      colour: COLOURS.layer,
      tooltip: 'A layer variable: a name and a value (a number, true/false, "text", or a list like [1, 2]).',
    },
    {
      type: RANDOM_SOURCE_BLOCK,
      message0: 'random %1 of type %2 seed %3 from %4 to %5',
      args0: [
        { type: 'field_input', name: 'NAME', text: 'random' },
        { type: 'field_dropdown', name: 'TYPE', options: RANDOM_TYPES.map((t) => [t, t]) },
        { type: 'field_number', name: 'SEED', value: 1, precision: 1 },
        { type: 'field_number', name: 'MIN', value: 0 },
        { type: 'field_number', name: 'MAX', value: 9 },
      ],
      previousStatement: CHECKS.random,
      nextStatement: CHECKS.random,
      colour: COLOURS.random,
      tooltip: 'A random input with a seed: the same seed gives the same values after Reset. "from" and "to" are used by int and long only.',
    },
  ],
  generators: {},
};
