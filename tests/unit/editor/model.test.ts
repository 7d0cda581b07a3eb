/** The controller editor's DOM-free logic: names, copying a layer, locks, code, text mode. */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import * as Blockly from 'blockly/core';
import type { ControllerSpec } from '../../../app/core/controller/model';
import { parseController } from '../../../app/core/formats';
import { validateController } from '../../../app/core/controller/validate';
import { tokenize } from '../../../app/renderer/editor/highlight';
import {
  blocksBodyFor,
  copyLayerInto,
  findFunction,
  functionCode,
  functionFrame,
  isFunctionLocked,
  isLayerLocked,
  lockViolation,
  renamedSource,
  textBodyOf,
  uniqueName,
  withBody,
} from '../../../app/renderer/editor/model';
import { OPEN_FIELD } from '../../../blocks/controller/function';
import { generateBody } from '../../../blocks/generate';
import { registerLayerbotBlocks } from '../../../blocks/index';
import { controllerToWorkspace, workspaceToController } from '../../../blocks/workspace';

const load = (name: string): ControllerSpec => {
  const file = join(__dirname, '..', '..', '..', 'examples', 'controllers', `${name}.controller.json`);
  const parsed = parseController(readFileSync(file, 'utf8'), file);
  if (!parsed.ok) throw new Error(JSON.stringify(parsed.problems));
  return parsed.value;
};

describe('unique names', () => {
  test('keeps a free name, numbers a taken one', () => {
    expect(uniqueName('steer', ['todo'])).toBe('steer');
    expect(uniqueName('steer', ['steer', 'steer2'])).toBe('steer3');
    expect(uniqueName('f2', ['f2'])).toBe('f3');
    expect(uniqueName('Middle', ['Middle'], true)).toBe('Middle 2');
    expect(uniqueName('Layer 2', ['Layer 2', 'Layer 3'], true)).toBe('Layer 4');
  });
});

describe('copying a layer from another controller', () => {
  test('renames what clashes and keeps the copy wired to itself', () => {
    const basic = load('basic');
    const copy = copyLayerInto(basic, basic.layers[1]);
    expect(copy.layer.name).toBe('Middle 2');
    expect(copy.layer.functions.map((f) => f.name)).toEqual(['arrived2', 'steer2']);
    expect(copy.renamed).toEqual(['layer Middle → Middle 2', 'arrived → arrived2', 'steer → steer2']);
    expect(copy.spec.layers.map((l) => l.name)).toEqual(['Top', 'Middle', 'Bottom', 'Middle 2']);
    // Arcs to other layers keep their names; nothing is missing here.
    const steer2 = copy.layer.functions[1];
    expect(steer2.inputs.find((i) => i.name === 'todo')?.from).toEqual({ kind: 'function', function: 'todo' });
    expect(copy.missing).toEqual([]);
    expect(validateController(copy.spec)).toEqual([]);
  });

  test('lists the functions the copy reads but this controller lacks; random sources are renamed too', () => {
    const random = load('basic-random');
    const lonely: ControllerSpec = { ...random, layers: [random.layers[random.layers.length - 1]] };
    const withRandom = random.layers.find((l) => l.randomSources.length)!;
    const copy = copyLayerInto(random, withRandom);
    for (const r of copy.layer.randomSources) expect(random.layers.flatMap((l) => l.randomSources.map((s) => s.name))).not.toContain(r.name);
    const readers = copy.layer.functions.flatMap((f) => f.inputs).filter((i) => i.from.kind === 'random');
    for (const i of readers) expect(copy.layer.randomSources.map((r) => r.name)).toContain((i.from as { source: string }).source);
    const top = copyLayerInto(lonely, random.layers[0]);
    expect(top.missing.length).toBeGreaterThan(0);
  });
});

describe('locks', () => {
  const basic = load('basic');
  const r = { locked: [{ layer: 'Bottom' }, { layer: 'Middle', function: 'arrived' }] };

  test('say which layers and functions are locked', () => {
    expect(isLayerLocked(r, 'Bottom')).toBe(true);
    expect(isLayerLocked(r, 'Middle')).toBe(false);
    expect(isFunctionLocked(r, 'Bottom', 'changePos')).toBe(true);
    expect(isFunctionLocked(r, 'Middle', 'arrived')).toBe(true);
    expect(isFunctionLocked(r, 'Middle', 'steer')).toBe(false);
    expect(isFunctionLocked(null, 'Bottom', 'changePos')).toBe(false);
  });

  test('an edit of a locked part is a violation; other edits and moving layers are not', () => {
    const setVar = (layer: number, value: number): ControllerSpec => ({
      ...basic,
      layers: basic.layers.map((l, i) => (i === layer ? { ...l, variables: l.variables.map((v, j) => (j === 0 ? { ...v, value } : v)) } : l)),
    });
    expect(lockViolation(basic, setVar(2, 99), r)).toMatch(/layer “Bottom” is locked/);
    expect(lockViolation(basic, setVar(0, 99), r)).toBeNull();
    expect(lockViolation(basic, setVar(2, 99), null)).toBeNull();
    const reordered = { ...basic, layers: [basic.layers[2], basic.layers[0], basic.layers[1]] };
    expect(lockViolation(basic, reordered, r)).toBeNull();
    const noArrived = withBody(basic, { layer: 'Middle', fn: 'arrived' }, { kind: 'text', code: 'return true;' });
    expect(lockViolation(basic, noArrived, r)).toMatch(/function “arrived” \(layer Middle\) is locked/);
    const steerText = withBody(basic, { layer: 'Middle', fn: 'steer' }, { kind: 'text', code: 'return "left";' });
    expect(lockViolation(basic, steerText, r)).toBeNull();
    expect(lockViolation(basic, { ...basic, layers: basic.layers.slice(0, 2) }, r)).toMatch(/Bottom/);
  });
});

describe('code and text mode', () => {
  const basic = load('basic');
  const found = findFunction(basic, { layer: 'Bottom', fn: 'lowLevelSteer' })!;

  test('a blocks function shows the declaration the engine runs', () => {
    const code = functionCode(found.fn, found.layer, generateBody);
    expect(code.kind).toBe('blocks');
    if (code.kind !== 'blocks') return;
    expect(code.source.startsWith("function lowLevelSteer(heading, steer) {\n'use strict';\nvar WHISKER_LENGTH = 6")).toBe(true);
    expect(code.source.trimEnd().endsWith('}')).toBe(true);
  });

  test('switching to text keeps the generated body; the frame is the header and the brace', () => {
    const result = textBodyOf(found.fn, found.layer, generateBody);
    expect('body' in result && result.body.kind === 'text' && result.body.code).toContain('return');
    const frame = functionFrame(found.fn, found.layer);
    expect(frame.header.split('\n')[0]).toBe('function lowLevelSteer(heading, steer) {');
    expect(frame.footer).toBe('}');
    const text = withBody(basic, { layer: 'Bottom', fn: 'lowLevelSteer' }, { kind: 'text', code: 'return heading;' });
    const shown = functionCode(findFunction(text, { layer: 'Bottom', fn: 'lowLevelSteer' })!.fn, found.layer, generateBody);
    expect(shown).toEqual({ kind: 'text', header: frame.header, code: 'return heading;', footer: '}' });
  });

  test('blocks that cannot become code give an error, and the body is kept', () => {
    const broken = withBody(basic, { layer: 'Bottom', fn: 'lowLevelSteer' }, blocksBodyFor());
    const fn = findFunction(broken, { layer: 'Bottom', fn: 'lowLevelSteer' })!.fn;
    const code = functionCode(fn, found.layer, generateBody);
    // An empty function block returns nothing: either fine or a readable error, never a throw.
    expect(['blocks', 'error']).toContain(code.kind);
    const bad = { ...fn, body: { kind: 'blocks' as const, blocks: { blocks: { languageVersion: 0, blocks: [{ type: 'no_such_block' }] } } } };
    const error = functionCode(bad, found.layer, generateBody);
    expect(error.kind).toBe('error');
    expect(textBodyOf(bad, found.layer, generateBody)).toHaveProperty('error');
  });

  test('renaming a function or random source renames arc sources', () => {
    expect(renamedSource('function:steer', 'function', 'steer', 'aim')).toBe('function:aim');
    expect(renamedSource('previous:steer', 'function', 'steer', 'aim')).toBe('previous:aim');
    expect(renamedSource('function:steering', 'function', 'steer', 'aim')).toBe('function:steering');
    expect(renamedSource('random:r', 'random', 'r', 'dice')).toBe('random:dice');
    expect(renamedSource('world:tick', 'function', 'tick', 'x')).toBe('world:tick');
  });
});

describe('the Code pane colouring', () => {
  test('tokens give the text back and mark keywords, strings, numbers, comments and the API', () => {
    const code = "var d = distance(a, [1, 2.5]); // near\nif (s == 'left') { return \"x\"; }";
    const tokens = tokenize(code);
    expect(tokens.map((t) => t.text).join('')).toBe(code);
    const kinds = (kind: string) => tokens.filter((t) => t.kind === kind).map((t) => t.text);
    expect(kinds('keyword')).toEqual(['var', 'if', 'return']);
    expect(kinds('number')).toEqual(['1', '2.5']);
    expect(kinds('string')).toEqual(["'left'", '"x"']);
    expect(kinds('comment')).toEqual(['// near']);
    expect(kinds('api')).toEqual(['distance']);
  });
});

describe('the function block', () => {
  test('its "open" button is not saved', () => {
    registerLayerbotBlocks();
    const basic = load('basic');
    const ws = new Blockly.Workspace();
    controllerToWorkspace(basic, ws);
    const fn = ws.getBlocksByType('lb_controller_function', false)[0];
    expect(fn.getField(OPEN_FIELD)).not.toBeNull();
    expect(JSON.stringify(Blockly.serialization.workspaces.save(ws))).not.toContain(OPEN_FIELD);
    expect(workspaceToController(ws, basic)).toEqual(basic);
    ws.dispose();
  });
});
