/**
 * The controller editor's workspace and the controller model, both ways:
 * `controllerToWorkspace` lays a controller out as layer blocks (top to bottom) holding their
 * variables, random sources and function blocks (with their arcs); `workspaceToController` reads
 * it back. Function bodies and descriptions ride on the function blocks as extra state.
 * Controller-level settings that have no block (name, description, body command, step budget)
 * come from `base`; layer descriptions too, matched by layer name.
 */
import * as Blockly from 'blockly/core';
import type { ArcSource, ControllerSpec, FunctionSpec, InputSpec, LayerSpec, LayerVariable, RandomSourceSpec, RandomType, WorldInputName } from '../app/core/controller/model';
import { RANDOM_TYPES, WORLD_INPUTS } from '../app/core/controller/model';
import type { JsonValue, ValueType } from '../app/core/values';
import { VALUE_TYPES } from '../app/core/values';
import { ARC_BLOCK, CONTROLLER_FUNCTION_BLOCK, functionExtra } from './controller/function';
import type { FunctionExtraState } from './controller/function';
import { LAYER_BLOCK, LAYER_VARIABLE_DEF_BLOCK, RANDOM_SOURCE_BLOCK } from './controller/layer';
import { registerLayerbotBlocks } from './index';
import { BlocksError } from './types';

type State = Blockly.serialization.blocks.State;

/** The text of an arc source in the arc block's dropdown. */
export function arcSourceText(from: ArcSource): string {
  switch (from.kind) {
    case 'function':
      return `function:${from.function}`;
    case 'previous':
      return `previous:${from.function}`;
    case 'world':
      return `world:${from.input}`;
    case 'random':
      return `random:${from.source}`;
  }
}

/** Parses an arc source back; `initial` is used by previous-tick sources. */
export function parseArcSource(text: string, initial: JsonValue, where: string): ArcSource {
  const i = text.indexOf(':');
  const kind = text.slice(0, i);
  const name = text.slice(i + 1);
  if (i > 0 && name) {
    if (kind === 'function') return { kind, function: name };
    if (kind === 'previous') return { kind, function: name, initial };
    if (kind === 'random') return { kind, source: name };
    if (kind === 'world' && (WORLD_INPUTS as readonly string[]).includes(name)) return { kind, input: name as WorldInputName };
  }
  throw new BlocksError(`${where}: choose where this input comes from.`);
}

function chain(states: State[]): State | undefined {
  for (let i = states.length - 2; i >= 0; i--) states[i].next = { block: states[i + 1] };
  return states[0];
}

function statement(states: State[]): { block: State } | undefined {
  const first = chain(states);
  return first ? { block: first } : undefined;
}

function arcState(input: InputSpec): State {
  const initial = input.from.kind === 'previous' ? JSON.stringify(input.from.initial) : 'null';
  return { type: ARC_BLOCK, fields: { NAME: input.name, SOURCE: arcSourceText(input.from), INITIAL: initial } };
}

function functionState(fn: FunctionSpec): State {
  const extra: FunctionExtraState = { body: fn.body as FunctionExtraState['body'] };
  if (fn.description !== undefined) extra.description = fn.description;
  const arcs = statement(fn.inputs.map(arcState));
  return {
    type: CONTROLLER_FUNCTION_BLOCK,
    fields: { NAME: fn.name, OUTPUT: fn.output },
    extraState: extra,
    ...(arcs ? { inputs: { ARCS: arcs } } : {}),
  };
}

function randomState(r: RandomSourceSpec): State {
  return { type: RANDOM_SOURCE_BLOCK, fields: { NAME: r.name, TYPE: r.type, SEED: r.seed, MIN: r.min ?? 0, MAX: r.max ?? 9 } };
}

/** A layer's block state (with its variables, random sources and functions), as the workspace holds it. */
export function layerState(layer: LayerSpec): State {
  const inputs: Record<string, { block: State }> = {};
  const vars = statement(layer.variables.map((v) => ({ type: LAYER_VARIABLE_DEF_BLOCK, fields: { NAME: v.name, VALUE: JSON.stringify(v.value) } })));
  const randoms = statement(layer.randomSources.map(randomState));
  const fns = statement(layer.functions.map(functionState));
  if (vars) inputs.VARIABLES = vars;
  if (randoms) inputs.RANDOM = randoms;
  if (fns) inputs.FUNCTIONS = fns;
  return { type: LAYER_BLOCK, fields: { NAME: layer.name }, inputs };
}

/** Replaces the workspace's contents with the controller's layers, top layer first. */
export function controllerToWorkspace(spec: ControllerSpec, workspace: Blockly.Workspace): void {
  registerLayerbotBlocks();
  const first = chain(spec.layers.map(layerState));
  workspace.clear();
  Blockly.serialization.workspaces.load({ blocks: { languageVersion: 0, blocks: first ? [{ ...first, x: 20, y: 20 }] : [] } }, workspace, { recordUndo: false });
}

function statementBlocks(block: Blockly.Block, input: string): Blockly.Block[] {
  const out: Blockly.Block[] = [];
  for (let b = block.getInputTargetBlock(input); b; b = b.getNextBlock()) if (b.isEnabled()) out.push(b);
  return out;
}

function parseJson(text: string, where: string): JsonValue {
  try {
    return JSON.parse(text) as JsonValue;
  } catch {
    throw new BlocksError(`${where}: "${text}" is not a value Layerbot understands (write a number, true, false, "text" in quotes, or a list like [1, 2]).`);
  }
}

function readFunction(block: Blockly.Block, layer: string): FunctionSpec {
  const name = String(block.getFieldValue('NAME'));
  const where = `Function "${name}" (layer "${layer}")`;
  const inputs: InputSpec[] = statementBlocks(block, 'ARCS').map((arc) => {
    const arcName = String(arc.getFieldValue('NAME'));
    const source = String(arc.getFieldValue('SOURCE') ?? '');
    const initial = source.startsWith('previous:') ? parseJson(String(arc.getFieldValue('INITIAL')), `${where}, input "${arcName}"`) : null;
    return { name: arcName, from: parseArcSource(source, initial, `${where}, input "${arcName}"`) };
  });
  const extra = functionExtra(block);
  const output = String(block.getFieldValue('OUTPUT')) as ValueType;
  return {
    name,
    ...(extra.description !== undefined ? { description: extra.description } : {}),
    output: (VALUE_TYPES as readonly string[]).includes(output) ? output : 'any',
    inputs,
    body: extra.body ?? { kind: 'blocks', blocks: null },
  };
}

function readLayer(block: Blockly.Block, base: ControllerSpec): LayerSpec {
  const name = String(block.getFieldValue('NAME'));
  const description = base.layers.find((l) => l.name === name)?.description;
  const variables: LayerVariable[] = statementBlocks(block, 'VARIABLES').map((v) => ({
    name: String(v.getFieldValue('NAME')),
    value: parseJson(String(v.getFieldValue('VALUE')), `Layer "${name}", variable "${String(v.getFieldValue('NAME'))}"`),
  }));
  const randomSources: RandomSourceSpec[] = statementBlocks(block, 'RANDOM').map((r) => {
    const type = String(r.getFieldValue('TYPE')) as RandomType;
    const ranged = type === 'int' || type === 'long';
    return {
      name: String(r.getFieldValue('NAME')),
      type: (RANDOM_TYPES as readonly string[]).includes(type) ? type : 'double',
      seed: Number(r.getFieldValue('SEED')),
      ...(ranged ? { min: Number(r.getFieldValue('MIN')), max: Number(r.getFieldValue('MAX')) } : {}),
    };
  });
  return {
    name,
    ...(description !== undefined ? { description } : {}),
    variables,
    randomSources,
    functions: statementBlocks(block, 'FUNCTIONS').map((f) => readFunction(f, name)),
  };
}

/**
 * Reads the controller back from the workspace. Layers are read from the stack of layer blocks
 * (the top block of the stack is the top layer; several stacks are read in Blockly's
 * top-to-bottom order of their first blocks). Function blocks outside a layer are not part of the controller.
 */
export function workspaceToController(workspace: Blockly.Workspace, base: ControllerSpec): ControllerSpec {
  const stacks = workspace.getTopBlocks(true).filter((b) => b.type === LAYER_BLOCK);
  const layers: LayerSpec[] = [];
  for (const top of stacks) for (let b: Blockly.Block | null = top; b; b = b.getNextBlock()) if (b.type === LAYER_BLOCK && b.isEnabled()) layers.push(readLayer(b, base));
  return { ...base, layers };
}
