/**
 * One block per entry of the native API table (app/core/sandbox/api.ts), made by one mechanism:
 * the table stays the single source of names, parameters, result types and tooltips. Only the
 * wording of each block's label lives here (API_LABELS), because it is presentation.
 *
 * This file has no side effects.
 */
import { Order } from 'blockly/javascript';
import type { ApiCategory, ApiEntry, ApiName } from '../../app/core/sandbox/api';
import { API } from '../../app/core/sandbox/api';
import type { ValueType } from '../../app/core/values';
import type { BlockFamily, BlockGenerator, BlockJson } from '../types';
import { COLOURS } from '../types';

/** Block labels; `%1`, `%2`... stand for the parameters in the table's order. */
export const API_LABELS: Partial<Record<ApiName, string>> = {
  distance: 'distance from %1 to %2',
  directionTo: 'direction from %1 to %2',
  normalizeAngle: 'angle %1 as a turn (-180 to 180)',
  normalizeHeading: 'angle %1 as a heading (0 to 360)',
  toRadians: '%1 degrees in radians',
  toDegrees: '%1 radians in degrees',
  pointAt: 'point from %1 in direction %2 at distance %3',
  segmentsIntersect: 'segment %1 crosses segment %2',
  touchesAnyWall: 'segment %1 touches a wall of %2',
  goalPosition: 'position of goal named %2 in goals %1',
  goalNames: 'names of goals %1',
  makeGrid: 'grid over walls %1 goals %2 robot at %3 cell size %4',
  makeGridWithRoom: 'grid over walls %1 goals %2 robot at %3 cell size %4 with room %5 around',
  cellOf: 'cell of point %2 in grid %1',
  cellCenter: 'centre of cell %2 in grid %1',
  inGrid: 'cell %2 is inside grid %1',
  cellsOfWall: 'cells that wall %2 passes through in grid %1',
  cellsNearWall: 'cells of grid %1 closer than %3 to wall %2',
  newGrid: 'new table for grid %1 with every cell set to %2',
  neighbourCell: 'cell next to %1 after action %2',
  copyList: 'copy of list %1',
  listWithout: 'list %1 without %2',
  moveToFront: 'list %1 with %2 moved to the front',
};

const CATEGORY_COLOURS: Record<ApiCategory, number> = {
  geometry: COLOURS.geometry,
  world: COLOURS.world,
  grid: COLOURS.grid,
  list: COLOURS.lists,
  output: COLOURS.text,
};

/** The Blockly type check of a value type (null: anything fits). */
export function checkOf(type: ValueType | null): string | null {
  switch (type) {
    case 'number':
      return 'Number';
    case 'boolean':
      return 'Boolean';
    case 'string':
      return 'String';
    case 'list':
    case 'point':
      return 'Array';
    default:
      return null;
  }
}

export const apiBlockType = (name: string): string => `lb_api_${name}`;

/** The input name of a parameter in block JSON (readable in controller files). */
export const apiInputName = (param: string): string => param.toUpperCase();

function words(name: string): string {
  return name.replace(/([A-Z])/g, ' $1').toLowerCase();
}

function definition(name: string, entry: ApiEntry): BlockJson {
  const label = API_LABELS[name as ApiName] ?? `${words(name)} ${entry.params.map((q, i) => `${q.name} %${i + 1}`).join(' ')}`;
  return {
    type: apiBlockType(name),
    message0: label,
    args0: entry.params.map((q) => ({ type: 'input_value', name: apiInputName(q.name), check: checkOf(q.type) })),
    inputsInline: entry.params.length <= 2,
    ...(entry.returns === null ? { previousStatement: null, nextStatement: null } : { output: checkOf(entry.returns) }),
    colour: CATEGORY_COLOURS[entry.category],
    tooltip: entry.doc,
  };
}

function generator(name: string, entry: ApiEntry): BlockGenerator {
  return (block, gen) => {
    const args = entry.params.map((q) => gen.requiredValue(block, apiInputName(q.name), Order.NONE, API_LABELS[name as ApiName] ? words(name) : name));
    const call = `${name}(${args.join(', ')})`;
    return entry.returns === null ? `${call};\n` : [call, Order.FUNCTION_CALL];
  };
}

const entries = Object.entries(API) as [string, ApiEntry][];

/** The API blocks of one category, in the table's order. */
export function apiBlocksOf(category: ApiCategory): string[] {
  return entries.filter(([, e]) => e.category === category).map(([n]) => apiBlockType(n));
}

export const apiBlocks: BlockFamily = {
  definitions: entries.map(([name, entry]) => definition(name, entry)),
  generators: Object.fromEntries(entries.map(([name, entry]) => [apiBlockType(name), generator(name, entry)])),
};
