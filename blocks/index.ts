/**
 * Registers every Layerbot block, field and generator with Blockly. Idempotent: call it as often
 * as you like (the app, the CLI's generator and the tests all do).
 */
import * as Blockly from 'blockly/core';
import 'blockly/blocks';
import * as En from 'blockly/msg/en';
import { javascriptGenerator } from 'blockly/javascript';
import { WORLD_INPUTS } from '../app/core/controller/model';
import { RESERVED_NAMES } from '../app/core/sandbox/api';
import { functionBlock } from './body/function';
import { nameBlocks } from './body/names';
import { returnBlock } from './body/return';
import { getFunctionContext } from './context';
import { ARC_BLOCK, CONTROLLER_FUNCTION_BLOCK, functionBlocks } from './controller/function';
import { layerBlocks, RANDOM_SOURCE_BLOCK } from './controller/layer';
import { apiBlocks } from './domain/api-blocks';
import { gridBlocks } from './domain/grid';
import { pointBlocks } from './domain/point';
import { FIELD_NAME_DROPDOWN, FieldNameDropdown, setNameOptions } from './fields/name-dropdown';
import { LayerbotGenerator, standardGenerators } from './generator';
import type { BlockFamily, BlockGenerator } from './types';

export const FAMILIES: readonly BlockFamily[] = [functionBlock, returnBlock, nameBlocks, apiBlocks, pointBlocks, gridBlocks, layerBlocks, functionBlocks];

let generator: LayerbotGenerator | null = null;

/** Layerbot's generator (registers the blocks on first use). */
export function layerbotGenerator(): LayerbotGenerator {
  registerLayerbotBlocks();
  return generator!;
}

/** The workspace whose names a block's dropdown lists (a flyout lists its target's). */
function homeWorkspace(block: Blockly.Block | null): Blockly.Workspace | null {
  if (!block) return null;
  const ws = block.workspace as Blockly.Workspace & { targetWorkspace?: Blockly.Workspace | null };
  return ws.targetWorkspace && !getFunctionContext(ws) ? ws.targetWorkspace : ws;
}

function arcSourceOptions(block: Blockly.Block | null): [string, string][] {
  const ws = homeWorkspace(block);
  const functions = ws ? ws.getBlocksByType(CONTROLLER_FUNCTION_BLOCK, true).map((b) => String(b.getFieldValue('NAME'))) : [];
  const randoms = ws ? ws.getBlocksByType(RANDOM_SOURCE_BLOCK, true).map((b) => String(b.getFieldValue('NAME'))) : [];
  return [
    ...functions.map((f): [string, string] => [`${f} (this tick)`, `function:${f}`]),
    ...functions.map((f): [string, string] => [`${f} (previous tick)`, `previous:${f}`]),
    ...WORLD_INPUTS.map((w): [string, string] => [`world: ${w}`, `world:${w}`]),
    ...randoms.map((r): [string, string] => [`random: ${r}`, `random:${r}`]),
  ];
}

let registered = false;

export function registerLayerbotBlocks(): void {
  if (registered) return;
  registered = true;
  Blockly.setLocale(En as unknown as Record<string, string>);
  if (!Blockly.registry.hasItem(Blockly.registry.Type.FIELD, FIELD_NAME_DROPDOWN)) Blockly.fieldRegistry.register(FIELD_NAME_DROPDOWN, FieldNameDropdown);
  const names = (kind: 'inputs' | 'variables') => (block: Blockly.Block | null) => (getFunctionContext(homeWorkspace(block))?.[kind] ?? []).map((n): [string, string] => [n, n]);
  setNameOptions('inputs', names('inputs'));
  setNameOptions('variables', names('variables'));
  setNameOptions('arcSources', arcSourceOptions);

  const ours: Record<string, BlockGenerator> = {};
  for (const family of FAMILIES) {
    for (const [name, fn] of Object.entries(family.extensions ?? {})) {
      if (!Blockly.Extensions.isRegistered(name)) Blockly.Extensions.register(name, fn);
    }
    for (const [name, mixin] of Object.entries(family.mutators ?? {})) {
      if (!Blockly.Extensions.isRegistered(name)) Blockly.Extensions.registerMutator(name, mixin);
    }
    Blockly.common.defineBlocks(Blockly.common.createBlockDefinitionsFromJsonArray(family.definitions.filter((d) => !Blockly.Blocks[d.type])));
    Object.assign(ours, family.generators);
  }
  generator = new LayerbotGenerator();
  Object.assign(generator.forBlock, standardGenerators(), ours);
  // The app's own uses of Blockly's generator get the same changes and reserved words.
  Object.assign(javascriptGenerator.forBlock, standardGenerators(), ours);
  javascriptGenerator.addReservedWords(RESERVED_NAMES.join(','));
}

export { ARC_BLOCK, CONTROLLER_FUNCTION_BLOCK };
