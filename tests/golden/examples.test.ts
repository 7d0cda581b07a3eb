/**
 * The example controllers, built from blocks. With UPDATE_EXAMPLES=1 the files in
 * examples/controllers/ are rewritten from tests/golden/examples/ (basic keeps the structure of
 * the committed basic.controller.json: names, arcs, descriptions, variables). Without it, the
 * committed files are checked: every function is made of blocks, and each example reaches its
 * known outcome (with the plain reference sandbox; the scenario tests run the real engine).
 */
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import type { ControllerSpec } from '../../app/core/controller/model';
import { parseController, serializeController } from '../../app/core/formats';
import { prettyJson } from '../../app/core/formats/pretty';
import { Session } from '../../app/core/session/session';
import type { WorldSpec } from '../../app/core/world/world';
import { generateBody } from '../../blocks/generate';
import { createPlainSandbox } from '../../app/cli/bench/plain-sandbox';
import { basicController, basicRandomController, nearestGoalController, valueIterationController } from './examples/controllers';
import { packWithExample, submissionWithExample } from './examples/packs';
import { office, trap, trapNew } from './examples/worlds';

const DIR = join(__dirname, '..', '..', 'examples', 'controllers');
const file = (name: string) => join(DIR, `${name}.controller.json`);
const PACK = join(__dirname, '..', '..', 'examples', 'packs', 'intro.pack.json');
const SOLUTION = join(__dirname, '..', '..', 'examples', 'packs', 'intro.solution.submission.json');
const readJson = (path: string) => JSON.parse(readFileSync(path, 'utf8')) as Record<string, unknown>;

function load(name: string): ControllerSpec {
  const parsed = parseController(readFileSync(file(name), 'utf8'), file(name));
  if (!parsed.ok) throw new Error(JSON.stringify(parsed.problems));
  return parsed.value;
}

if (process.env.UPDATE_EXAMPLES === '1') {
  const basic = load('basic');
  const built: Record<string, ControllerSpec> = {
    basic: basicController(basic),
    'basic-random': basicRandomController(basic),
    'nearest-goal': nearestGoalController(basic),
    'value-iteration': valueIterationController(basic),
  };
  for (const [name, spec] of Object.entries(built)) writeFileSync(file(name), serializeController(spec));
  const vi = load('value-iteration');
  writeFileSync(PACK, prettyJson(packWithExample(readJson(PACK), vi)));
  writeFileSync(SOLUTION, prettyJson(submissionWithExample(readJson(SOLUTION), vi)));
}

function run(controller: string, world: WorldSpec, ticks = 2000) {
  const s = new Session(world, load(controller), { sandbox: createPlainSandbox, generateBody });
  const summary = s.run(ticks);
  s.dispose();
  return { ticks: summary.ticks, crashTick: summary.crashTick, goals: summary.goals.map((g) => g.reachedTick), error: summary.error };
}

describe('example controllers (blocks)', () => {
  test.each(['basic', 'basic-random', 'nearest-goal', 'value-iteration'])('%s is made of blocks only', (name) => {
    for (const layer of load(name).layers) for (const fn of layer.functions) expect([fn.name, fn.body.kind]).toEqual([fn.name, 'blocks']);
  });

  test('basic: the textbook robot (127, 43, 46, 68 ticks; crashes in the trap at tick 93)', () => {
    expect(run('basic', office)).toEqual({ ticks: 284, crashTick: null, goals: [127, 170, 216, 284], error: null });
    expect(run('basic', trap)).toEqual({ ticks: 93, crashTick: 93, goals: [null], error: null });
    expect(run('basic', trapNew)).toEqual({ ticks: 100, crashTick: 100, goals: [null], error: null });
  });

  test('basic-random: seeded, so the same run every time', () => {
    expect(run('basic-random', office)).toEqual(run('basic-random', office));
    expect(run('basic-random', office).goals).toEqual([127, 170, 216, 284]);
  });

  test('nearest-goal: visits the nearest unreached goal first', () => {
    const r = run('nearest-goal', office, 400);
    expect(r.crashTick).toBeNull();
    expect(r.goals.slice(0, 2)).toEqual([131, 174]);
  });

  test('the sample pack\'s value-iteration starters and solutions are the example (starters keep their CELL_SIZE)', () => {
    const vi = load('value-iteration');
    expect(readJson(PACK)).toEqual(packWithExample(readJson(PACK), vi));
    expect(readJson(SOLUTION)).toEqual(submissionWithExample(readJson(SOLUTION), vi));
  });

  test('value-iteration: completes the office plan and escapes both traps without crashing', () => {
    expect(run('value-iteration', office)).toEqual({ ticks: 290, crashTick: null, goals: [120, 162, 209, 290], error: null });
    expect(run('value-iteration', trap)).toEqual({ ticks: 117, crashTick: null, goals: [117], error: null });
    expect(run('value-iteration', trapNew)).toEqual({ ticks: 141, crashTick: null, goals: [141], error: null });
  });
});
