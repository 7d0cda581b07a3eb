/** Reading packs and submissions: every problem names the file, the challenge and the JSON path. */
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';
import { parsePack, parseSubmission, TOOLBOX_CATEGORIES } from '../../../app/core/packs';
import { CATEGORY_NAMES } from '../../../blocks/toolbox';
import { ROOT } from '../../support/examples';
import { challenge, controller, pack, packJson, submissionJson, world } from './fixtures';
import type { Json } from './fixtures';

function problems(json: unknown): string[] {
  const text = typeof json === 'string' ? json : JSON.stringify(json, null, 2);
  const parsed = parsePack(text, 'bad.pack.json');
  if (parsed.ok) throw new Error('expected problems');
  return parsed.problems.map((p) => `${p.path}: ${p.message}`);
}

describe('parsePack', () => {
  test('reads a good pack, filling in defaults', () => {
    const p = pack([challenge({ maxTicks: undefined, locked: undefined, hints: undefined })]);
    expect(p.challenges[0]).toMatchObject({ id: 'east', maxTicks: 2000, locked: [], hints: [], criteria: [{ kind: 'reachGoals', order: 'plan' }, { kind: 'noCrash' }] });
    expect(Object.isFrozen(p.challenges[0].world)).toBe(true);
  });

  test('invalid JSON says where', () => {
    expect(problems('{"format": "layerbot-pack",\n "version": 1,}')[0]).toMatch(/^\$: not valid JSON at line 2/);
  });

  test('an unknown world field names the challenge and the path inside the pack', () => {
    expect(problems(packJson([challenge({ world: world({ colour: 'red' }) })]))).toEqual([
      '$.challenges[0].world.colour: challenge "east": unknown field "colour"; allowed: format, version, name, description, walls, goals, plan, robot, goalRadius, bounds, body',
    ]);
  });

  test('line numbers point into the pack file', () => {
    const text = JSON.stringify(packJson([challenge({ world: world({ colour: 'red' }) })]), null, 2);
    const parsed = parsePack(text, 'bad.pack.json');
    const line = text.split('\n').findIndex((l) => l.includes('"colour"')) + 1;
    expect(parsed.ok ? null : parsed.problems[0].line).toBe(line);
  });

  test('a starter with a graph problem is named by its path', () => {
    const starter = controller();
    ((starter.layers as Json[])[1].functions as Json[])[0].inputs = [{ name: 'speed', from: { kind: 'function', function: 'sped' } }];
    expect(problems(packJson([challenge({ starter })]))).toEqual([
      '$.challenges[0].starter.layers[1].functions[0].inputs[0].from: challenge "east": Function "changePos" (layer "Bottom"), input "speed" reads the function "sped", but there is no function by that name. Did you mean "speed"?',
    ]);
  });

  test('criteria naming missing goals, in the world and in variants', () => {
    const variant = world({ name: 'Short corridor', goals: [{ name: 'a', x: 5, y: 0 }], plan: ['a'] });
    expect(
      problems(packJson([challenge({ criteria: [{ kind: 'reachGoals', goals: ['a', 'bb'], order: 'any' }, { kind: 'variants', worlds: [variant] }] })])),
    ).toEqual([
      '$.challenges[0].criteria[0].goals[1]: challenge "east": no goal is named "bb" in the challenge world (did you mean "b"?); its goals are: a, b, c',
      '$.challenges[0].criteria[0].goals[1]: challenge "east": no goal is named "bb" in variant world 1 ("Short corridor"); its goals are: a',
    ]);
  });

  test('locks naming missing layers and functions; duplicate ids; ticks beyond the limit', () => {
    const second = challenge({ locked: [{ layer: 'Middle' }, { layer: 'Top', function: 'sped' }], criteria: [{ kind: 'withinTicks', ticks: 500 }] });
    expect(problems(packJson([challenge(), second]))).toEqual([
      '$.challenges[1].id: challenge "east": two challenges have the id "east" (challenges 1 and 2); ids must differ, because submissions name challenges by id',
      `$.challenges[1].criteria[0].ticks: challenge "east": 500 ticks is more than the challenge's tick limit (100), so runs stop before it; lower it or raise maxTicks`,
      '$.challenges[1].locked[0].layer: challenge "east": the starter has no layer "Middle"; its layers are: Top, Bottom',
      '$.challenges[1].locked[1].function: challenge "east": layer "Top" of the starter has no function "sped" (did you mean "speed"?); its functions are: speed',
    ]);
  });

  test('shape problems: unknown criterion kind, bad toolbox category, bad id', () => {
    expect(problems(packJson([challenge({ id: 'East 1', toolbox: ['Logic', 'Magic'], criteria: [{ kind: 'reachGoal' }] })]))).toEqual([
      '$.challenges[0].id: challenge "East 1": must match the pattern ^[a-z0-9][a-z0-9-]*$, found "East 1"',
      '$.challenges[0].toolbox[1]: challenge "East 1": must be one of: Inputs, Logic, Loops, Math, Text, Lists, Geometry, World, Grid, Variables, Helpers; found "Magic"',
      '$.challenges[0].criteria[0].kind: challenge "East 1": must be one of: reachGoals, withinTicks, noCrash, noError, maxBlocks, hasFunction, variants; found "reachGoal" (did you mean "reachGoals"?)',
    ]);
  });

  test('a world file is not a pack', () => {
    expect(problems(world())).toEqual(['$.format: this file is a Layerbot world, not a challenge pack; open it as a world']);
  });

  test('the toolbox categories are the block toolbox categories', () => {
    expect([...TOOLBOX_CATEGORIES]).toEqual([...CATEGORY_NAMES]);
  });

  test('the generated validators are up to date', () => {
    expect(() => execFileSync(process.execPath, [join(ROOT, 'app/core/packs/build-validators.cjs'), '--check'], { stdio: 'pipe' })).not.toThrow();
  });
});

describe('parseSubmission', () => {
  test('reads controllers by challenge id', () => {
    const parsed = parseSubmission(JSON.stringify(submissionJson({ east: controller() })), 'ada.submission.json');
    expect(parsed.ok && Object.keys(parsed.value.controllers)).toEqual(['east']);
  });

  test('a malformed controller is named by its challenge id', () => {
    const parsed = parseSubmission(JSON.stringify(submissionJson({ 'steer-one': { ...controller(), layers: 3 } })), 'ada.submission.json');
    expect(parsed.ok ? [] : parsed.problems.map((p) => `${p.path}: ${p.message}`)).toEqual(['$.controllers["steer-one"].layers: expected a list [...], found 3']);
  });

  test('a controller file is not a submission', () => {
    const parsed = parseSubmission(JSON.stringify(controller()), 'east.controller.json');
    expect(parsed.ok ? '' : parsed.problems[0].message).toMatch(/single controller, not a submission/);
  });
});
