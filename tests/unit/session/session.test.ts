import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { ControllerSpec } from '../../../app/core/controller/model';
import { ControllerInvalidError, Session } from '../../../app/core/session/session';
import { createPlainSandbox } from '../../../app/cli/bench/plain-sandbox';
import { controller, fn, forward, layer, world } from '../../support/controllers';

const opts = { sandbox: createPlainSandbox, generateBody: null };

describe('session', () => {
  test('tick 0 is the initial state; each step records one tick', () => {
    const s = new Session(world, controller([layer('Bottom', [forward()])]), opts);
    expect(s.tick).toBe(0);
    expect(s.history.at(0).outputs).toEqual([]);
    s.step();
    expect(s.tick).toBe(1);
    expect(s.history.at(1).world.robot.x).toBeCloseTo(1);
  });

  test('runs until the plan is complete', () => {
    const s = new Session(world, controller([layer('Bottom', [forward()])]), opts);
    const summary = s.run(100);
    expect(summary).toEqual({ ticks: 8, crashed: false, crashTick: null, goals: [{ name: 'g', reachedTick: 8 }], error: null });
    expect(s.status).toBe('done');
  });

  test('previous-tick arcs carry the initial value on tick 1, then the previous output', () => {
    const c = controller([
      layer('Top', [fn('count', 'number', [{ name: 'before', from: { kind: 'previous', function: 'count', initial: 10 } }], 'return before + 1;')]),
      layer('Bottom', [forward()]),
    ]);
    const s = new Session(world, c, opts);
    s.run(3);
    expect([1, 2, 3].map((t) => s.history.at(t).outputs[0])).toEqual([11, 12, 13]);
  });

  test('world inputs are read from the world after the previous tick', () => {
    const c = controller([layer('Bottom', [fn('seen', 'point', [{ name: 'p', from: { kind: 'world', input: 'robotPos' } }], 'return p;'), forward()])]);
    const s = new Session(world, c, opts);
    s.run(2);
    expect(s.history.at(1).outputs[0]).toEqual([0, 0]);
    expect((s.history.at(2).outputs[0] as number[])[0]).toBeCloseTo(1);
  });

  test('a wrong output type stops the run with the function, layer and both types named', () => {
    const c = controller([layer('Middle', [fn('steer', 'string', [], 'return 3;')]), layer('Bottom', [forward()])]);
    const s = new Session(world, c, opts);
    const summary = s.run(10);
    expect(summary.ticks).toBe(1);
    expect(summary.error).toBe('Error in function "steer" (layer "Middle"): it should return a text, but it returned a number (3).');
    expect(s.status).toBe('error');
    expect(s.history.at(1).world).toBe(s.history.at(0).world);
  });

  test('a function returning nothing is explained', () => {
    const c = controller([layer('Bottom', [fn('changePos', 'move', [], 'var x = 1;')])]);
    expect(new Session(world, c, opts).run(5).error).toContain('it should return a move {heading, dx, dy}, but it returned nothing');
  });

  test('invalid controllers are refused with every problem', () => {
    expect(() => new Session(world, controller([layer('Bottom', [])]), opts)).toThrow(ControllerInvalidError);
  });

  test('edits while running are recorded at their tick', () => {
    const s = new Session(world, controller([layer('Bottom', [forward()])]), opts);
    s.run(3);
    s.editWorld({ type: 'moveRobot', x: 0, y: 5 });
    expect(s.history.at(3).edits).toEqual([{ type: 'moveRobot', x: 0, y: 5 }]);
    expect(s.history.at(3).world.robot.y).toBe(5);
    s.step();
    expect(s.history.at(4).world.robot.y).toBe(5);
    expect(s.history.at(4).world.robot.x).toBeCloseTo(1);
  });

  test('printed lines are kept with the tick and the function', () => {
    const c = controller([layer('Bottom', [fn('talk', 'number', [{ name: 't', from: { kind: 'world', input: 'tick' } }], "print('tick ' + t); return t;"), forward()])]);
    const s = new Session(world, c, opts);
    s.run(2);
    expect(s.history.at(2).printed).toEqual([{ function: 'talk', layer: 'Bottom', text: 'tick 2' }]);
  });

  test('random sources replay exactly after a reset', () => {
    const c = controller([
      layer('Top', [fn('roll', 'number', [{ name: 'r', from: { kind: 'random', source: 'dice' } }], 'return r;')], {
        randomSources: [{ name: 'dice', type: 'int', seed: 42, min: 1, max: 6 }],
      }),
      layer('Bottom', [forward()]),
    ]);
    const s = new Session({ ...world, plan: [] }, c, opts);
    s.run(20);
    const first = [...s.history.slice(1)].map((r) => r.outputs[0]);
    expect(new Set(first).size).toBeGreaterThan(1);
    expect(first.every((v) => Number.isInteger(v) && (v as number) >= 1 && (v as number) <= 6)).toBe(true);
    s.reset();
    s.run(20);
    expect([...s.history.slice(1)].map((r) => r.outputs[0])).toEqual(first);
  });

  test('arcs show values at a tick and whether they changed', () => {
    const c = controller([
      layer('Top', [fn('count', 'number', [{ name: 'before', from: { kind: 'previous', function: 'count', initial: 0 } }, { name: 'c', from: { kind: 'world', input: 'crashed' } }], 'return before + 1;')]),
      layer('Bottom', [forward()]),
    ]);
    const s = new Session(world, c, opts);
    s.run(3);
    expect(s.arcs(3)).toEqual([
      { from: 'previous.count', to: 'count', input: 'before', previousTick: true, value: 2, changed: true },
      { from: 'world.crashed', to: 'count', input: 'c', previousTick: false, value: false, changed: false },
    ]);
  });

  test('the textbook basic controller reproduces the textbook robot', () => {
    const spec = JSON.parse(readFileSync(join(__dirname, '../../../examples/controllers/basic.controller.json'), 'utf8')) as ControllerSpec;
    if (spec.layers.some((l) => l.functions.some((f) => f.body.kind !== 'text'))) return; // the blocks version is covered by the scenario tests
    const office = {
      name: 'office',
      walls: [[[20, 0], [30, 20]], [[70, -5], [70, 25]]] as const,
      goals: [{ name: 'mail', x: -5, y: 10 }, { name: 'o103', x: 50, y: 10 }, { name: 'o109', x: 100, y: 10 }, { name: 'storage', x: 101, y: 51 }],
      plan: ['o109', 'storage', 'o109', 'o103'],
      robot: { x: 0, y: 0, heading: 90 },
    };
    const s = new Session(office as never, spec, opts);
    expect(s.run(2000).goals.map((g) => g.reachedTick)).toEqual([127, 170, 216, 284]);
  });
});

describe('history sharing', () => {
  test('an output equal to the previous tick\'s is stored as the same object (SPEC T12, DESIGN history)', () => {
    const c = controller([
      layer('Top', [fn('grid', 'list', [], 'var g = []; for (var r = 0; r < 3; r++) { g.push([r, r + 1]); } return g;')]),
      layer('Bottom', [forward()]),
    ]);
    const s = new Session({ ...world, plan: [] }, c, opts);
    s.run(5);
    const outputs = [...s.history.slice(1)].map((r) => r.outputs[0]);
    expect(outputs[0]).toEqual([[0, 1], [1, 2], [2, 3]]);
    for (const o of outputs) expect(o).toBe(outputs[0]);
  });
});
