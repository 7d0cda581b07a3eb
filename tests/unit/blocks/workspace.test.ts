/** Controller <-> workspace, headless: the controller editor's layers, functions, arcs and random sources. */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import * as Blockly from 'blockly/core';
import { parseController } from '../../../app/core/formats';
import type { ControllerSpec } from '../../../app/core/controller/model';
import { ARC_BLOCK, CONTROLLER_FUNCTION_BLOCK } from '../../../blocks/controller/function';
import { registerLayerbotBlocks } from '../../../blocks/index';
import { makeControllerToolbox, makeToolbox, CATEGORY_NAMES } from '../../../blocks/toolbox';
import { controllerToWorkspace, workspaceToController } from '../../../blocks/workspace';

const load = (name: string): ControllerSpec => {
  const file = join(__dirname, '..', '..', '..', 'examples', 'controllers', `${name}.controller.json`);
  const parsed = parseController(readFileSync(file, 'utf8'), file);
  if (!parsed.ok) throw new Error(JSON.stringify(parsed.problems));
  return parsed.value;
};

describe('controller workspace', () => {
  beforeAll(() => registerLayerbotBlocks());

  test.each(['basic', 'basic-random', 'nearest-goal', 'value-iteration'])('%s round-trips through the workspace', (name) => {
    const spec = load(name);
    const ws = new Blockly.Workspace();
    controllerToWorkspace(spec, ws);
    expect(workspaceToController(ws, spec)).toEqual(spec);
    // And through Blockly's own serialization (what the app saves and restores).
    const saved = Blockly.serialization.workspaces.save(ws);
    const again = new Blockly.Workspace();
    Blockly.serialization.workspaces.load(saved, again);
    // Without a base, layer descriptions (which have no block) are not known.
    const withoutDescriptions = spec.layers.map(({ description: _d, ...l }) => l);
    expect(workspaceToController(again, { ...spec, layers: [] })).toEqual({ ...spec, layers: withoutDescriptions });
    ws.dispose();
    again.dispose();
  });

  test('editing blocks changes the controller: rename, arcs, reorder layers', () => {
    const spec = load('basic');
    const ws = new Blockly.Workspace();
    controllerToWorkspace(spec, ws);
    const timer = ws.getBlocksByType(CONTROLLER_FUNCTION_BLOCK, false).find((b) => b.getFieldValue('NAME') === 'timer')!;
    timer.setFieldValue('clock', 'NAME');
    const arc = timer.getInputTargetBlock('ARCS')!;
    expect(arc.type).toBe(ARC_BLOCK);
    arc.setFieldValue('world:tick', 'SOURCE');
    const out = workspaceToController(ws, spec);
    const clock = out.layers[0].functions.find((f) => f.name === 'clock')!;
    expect(clock.inputs[0].from).toEqual({ kind: 'world', input: 'tick' });
    expect(clock.body).toEqual(spec.layers[0].functions.find((f) => f.name === 'timer')!.body);
    ws.dispose();
  });

  test('a layer variable that is not a value is explained', () => {
    const spec = load('basic');
    const ws = new Blockly.Workspace();
    controllerToWorkspace(spec, ws);
    ws.getBlocksByType('lb_layer_variable_def', false)[0].setFieldValue('two hundred', 'VALUE');
    expect(() => workspaceToController(ws, spec)).toThrow(/Layer "Top", variable "TIMEOUT": "two hundred" is not a value/);
    ws.dispose();
  });

  test('the arc dropdown lists every function (this and previous tick), world input and random source', () => {
    const spec = load('basic-random');
    const ws = new Blockly.Workspace();
    controllerToWorkspace(spec, ws);
    const arc = ws.getBlocksByType(ARC_BLOCK, false)[0];
    const values = (arc.getField('SOURCE') as Blockly.FieldDropdown).getOptions(false).map((o) => o[1]);
    expect(values).toEqual(expect.arrayContaining(['function:todo', 'previous:timer', 'world:robotPos', 'random:draw']));
    ws.dispose();
  });
});

describe('toolbox', () => {
  test('offers every category by default, in order, without unseeded random blocks', () => {
    const toolbox = makeToolbox();
    const names = ((toolbox as { contents: unknown[] }).contents as { name: string }[]).map((c) => c.name);
    expect(names).toEqual(CATEGORY_NAMES);
    expect(JSON.stringify(toolbox)).not.toMatch(/math_random/);
    expect(names).toEqual(expect.arrayContaining(['Inputs', 'Logic', 'Loops', 'Math', 'Text', 'Lists', 'Geometry', 'World', 'Grid', 'Variables']));
  });

  test('can be limited to some categories (challenge packs); unknown names are refused', () => {
    expect(((makeToolbox(['Inputs', 'Logic']) as { contents: unknown[] }).contents as { name: string }[]).map((c) => c.name)).toEqual(['Inputs', 'Logic']);
    expect(() => makeToolbox(['Magic'])).toThrow(/Unknown toolbox categories: Magic/);
  });

  test('every block in the toolboxes is registered', () => {
    registerLayerbotBlocks();
    const types = JSON.stringify([makeToolbox(), makeControllerToolbox()]).match(/"type":"[^"]+"/g)!.map((t) => t.slice(8, -1));
    for (const t of types) expect([t, Blockly.Blocks[t] !== undefined]).toEqual([t, true]);
  });

  test('API blocks take their tooltip from the API table', () => {
    registerLayerbotBlocks();
    const ws = new Blockly.Workspace();
    const block = ws.newBlock('lb_api_distance');
    expect(block.getTooltip()).toBe('The distance between two points.');
    ws.dispose();
  });
});
