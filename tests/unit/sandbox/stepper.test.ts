/**
 * The stepper ("Step into"): a function replayed block by block with the inputs it received at a
 * tick gives exactly what the run recorded at that tick (SPEC T12), spends the step budget as the
 * run does, and stops where each kind of step says.
 */
import { allFunctions } from '../../../app/core/controller/model';
import { createInterpreterSandbox } from '../../../app/core/sandbox/interpreter';
import type { StepView } from '../../../app/core/sandbox/stepper';
import { debugListing, Stepper } from '../../../app/core/sandbox/stepper';
import type { CompiledFunction } from '../../../app/core/sandbox/types';
import type { Session } from '../../../app/core/session/session';
import { sameValue } from '../../../app/core/values';
import { exampleSession } from '../../support/examples';
import { controller, fn as textFn, forward, layer, world } from '../../support/controllers';
import { Session as SessionClass } from '../../../app/core/session/session';

/** A function with a debug source written by hand: `#id` lines become `__block('id');`. */
function debugFn(name: string, params: string[], lines: string[]): CompiledFunction {
  const debug = lines.map((l) => l.replace(/^(\s*)#(\S+)$/, "$1__block('$2');")).join('\n');
  const plain = lines.filter((l) => !/^\s*#\S+$/.test(l)).join('\n');
  const wrap = (body: string) => `function ${name}(${params.join(', ')}) {\n'use strict';\n${body}\n}`;
  return { name, layer: 'L', params, source: wrap(plain), debugSource: wrap(debug) };
}

/** Steps with `step` until the call ends; the block ids stopped at, and the last view. */
function walk(s: Stepper, step: (s: Stepper) => StepView): { ids: string[]; last: StepView } {
  const ids: string[] = [];
  let v = s.current();
  for (let n = 0; n < 100_000 && !v.done; n++) {
    v = step(s);
    if (!v.done && v.blockId !== null) ids.push(v.blockId);
  }
  return { ids, last: v };
}

/** The inputs function `i` received at `tick`, as the arc table reports them. */
function inputsAt(session: Session, tick: number, i: number): unknown[] {
  return session.functions[i].fn.inputs.map((_, j) => session.arcValue(tick, i, j));
}

function stepperFor(session: Session, tick: number, i: number): Stepper {
  const { fn, layer: l } = session.functions[i];
  return new Stepper({
    fn: session.compiled[i],
    args: inputsAt(session, tick, i),
    budget: session.controller.stepBudget ?? 5_000_000,
    output: fn.output,
    layerVariables: l.variables.map((v) => v.name),
  });
}

describe('debugListing', () => {
  test('drops the markers and maps each block to its first statement line', () => {
    const f = debugFn('f', ['a'], ['var x;', '#b1', 'x = a;', 'for (;;) {', '  #b2', '  x++;', '  #b1', '}', '#b3', 'return x;']);
    const listing = debugListing(f.debugSource!);
    expect(listing.lines).toEqual(f.source.split('\n'));
    expect(listing.lines[listing.blockLines.get('b1')!]).toBe('x = a;');
    expect(listing.lines[listing.blockLines.get('b2')!]).toBe('  x++;');
    expect(listing.lines[listing.blockLines.get('b3')!]).toBe('return x;');
  });
});

describe('replaying the examples gives what the run recorded', () => {
  const cases: [string, string, number, number[]][] = [
    ['basic', 'office', 140, [1, 2, 3, 10, 60, 127, 128, 140]],
    ['basic', 'trap', 93, [1, 40, 93]],
    ['nearest-goal', 'office', 60, [1, 2, 30, 60]],
    ['value-iteration', 'office', 12, [1, 2, 12]],
  ];
  test.each(cases)('%s in %s', (name, worldName, ticks, sample) => {
    const session = exampleSession(name, worldName);
    session.run(ticks);
    expect(session.tick).toBe(ticks);
    const plain = createInterpreterSandbox(session.compiled);
    let compared = 0;
    for (const tick of sample) {
      const outputs = session.history.at(tick).outputs;
      const printed = session.history.at(tick).printed;
      session.functions.forEach(({ fn }, i) => {
        const args = inputsAt(session, tick, i);
        // Continue: the result, the printed lines and the steps of the run.
        const s = stepperFor(session, tick, i);
        const end = s.continue();
        expect(end.error).toBeUndefined();
        expect(sameValue(end.result, outputs[i])).toBe(true);
        expect(end.printed).toEqual(printed.filter((p) => p.function === fn.name).map((p) => p.text));
        const run = plain.call(i, args, 5_000_000);
        expect(run.ok && run.steps).toBe(end.steps);
        // Block by block: the same result; each stop is one of the function's blocks, in code order
        // the first time round.
        s.restart();
        const { ids, last } = walk(s, (x) => x.stepInto());
        expect(sameValue(last.result, outputs[i])).toBe(true);
        expect(last.steps).toBe(end.steps);
        const listing = s.listing;
        expect(ids.length).toBeGreaterThan(0);
        for (const id of ids) expect(listing.blockLines.has(id)).toBe(true);
        expect(ids[0]).toBe([...listing.blockLines.keys()][0]);
        s.dispose();
        compared++;
      });
    }
    plain.dispose();
    expect(compared).toBe(sample.length * session.functions.length);
    session.dispose();
  }, 60_000);

  test('steer at tick 3 of the basic controller: blocks in order, locals as they are set', () => {
    const session = exampleSession('basic', 'office');
    session.run(3);
    const i = session.functions.findIndex((f) => f.fn.name === 'steer');
    const s = stepperFor(session, 3, i);
    expect(s.current()).toMatchObject({ blockId: null, done: false, function: 'steer', layer: 'Middle' });
    const first = s.stepBlock();
    expect(first.blockId).toBe('steer.4');
    expect(s.listing.lines[first.line!]).toContain('if (whisker)');
    const inputs = first.locals.filter((l) => l.kind === 'input');
    expect(inputs.map((l) => l.name)).toEqual(['robotPos', 'heading', 'whisker', 'todo', 'goals']);
    expect(inputs.map((l) => l.value)).toEqual(inputsAt(session, 3, i));
    expect(first.locals.filter((l) => l.kind === 'layer').map((l) => [l.name, l.value])).toEqual([
      ['CLOSE', 2],
      ['STRAIGHT', 11],
    ]);
    const dx = () => s.current().locals.find((l) => l.name === 'dx');
    expect(dx()).toEqual({ name: 'dx', kind: 'variable', value: undefined });
    const seen = [first.blockId];
    while (s.current().blockId !== 'steer.21') seen.push(s.stepBlock().blockId);
    expect(seen).toEqual(['steer.4', 'steer.9', 'steer.15', 'steer.21']);
    // steer.15 (dx = ...) has run.
    const goal = s.current().locals.find((l) => l.name === 'goal')!.value as number[];
    const robot = inputsAt(session, 3, i)[0] as number[];
    expect(dx()!.value).toBe(goal[0] - robot[0]);
    const end = s.continue();
    expect(end).toMatchObject({ done: true, blockId: null, result: session.history.at(3).outputs[i] });
    // Done: further steps change nothing.
    expect(s.stepBlock()).toEqual(end);
    s.dispose();
    session.dispose();
  });
});

describe('kinds of step', () => {
  const f = debugFn('f', ['n'], [
    'var total, k;',
    'function twice(x) {',
    '  #h0',
    '  var y;',
    '  #h1',
    '  y = x * 2;',
    '  #h2',
    '  return y;',
    '}',
    '#a',
    'total = 0;',
    '#b',
    'for (k = 0; k < n; k++) {',
    '  #c',
    '  total = total + twice(k);',
    '  #b',
    '}',
    '#d',
    'print(total);',
    '#e',
    'return total;',
  ]);
  const make = (budget = 100_000) => new Stepper({ fn: f, args: [2], budget, output: 'number' });

  test('Step stays in the function: a loop block is met again each round; helpers run through', () => {
    const s = make();
    const { ids, last } = walk(s, (x) => x.stepBlock());
    expect(ids).toEqual(['a', 'b', 'c', 'b', 'c', 'b', 'd', 'e']);
    expect(last).toMatchObject({ done: true, result: 2, printed: ['2'] });
    s.dispose();
  });

  test('Step into enters the helper; Step out returns to the caller', () => {
    const s = make();
    const { ids } = walk(s, (x) => x.stepInto());
    expect(ids).toEqual(['a', 'b', 'c', 'h0', 'h1', 'h2', 'b', 'c', 'h0', 'h1', 'h2', 'b', 'd', 'e']);
    s.restart();
    for (const id of ['a', 'b', 'c']) expect(s.stepInto().blockId).toBe(id);
    const inHelper = s.stepInto();
    expect(inHelper.blockId).toBe('h0');
    expect(inHelper.frames.map((fr) => fr.function)).toEqual(['twice', 'f']);
    expect(inHelper.locals).toEqual([
      { name: 'x', kind: 'parameter', value: 0 },
      { name: 'y', kind: 'variable', value: undefined },
    ]);
    expect(inHelper.frames[1].locals).toEqual([
      { name: 'n', kind: 'input', value: 2 },
      { name: 'total', kind: 'variable', value: 0 },
      { name: 'k', kind: 'variable', value: 0 },
    ]);
    // Step inside the helper stays there.
    expect(s.stepBlock().blockId).toBe('h1');
    // Out: back to the caller's next block.
    const out = s.stepOut();
    expect(out.blockId).toBe('b');
    expect(out.frames.map((fr) => fr.function)).toEqual(['f']);
    expect(out.locals.find((l) => l.name === 'total')!.value).toBe(0);
    // Out at the function's own level runs to the end.
    expect(s.stepOut()).toMatchObject({ done: true, result: 2 });
    s.dispose();
  });

  test('in slices: a step under way is busy until it reaches its stop', () => {
    const s = make();
    s.start('end');
    let v = s.run(5);
    expect(v).toMatchObject({ busy: true, done: false });
    let slices = 1;
    while (!v.done) {
      v = s.run(5);
      slices++;
    }
    expect(slices).toBeGreaterThan(10);
    expect(v).toMatchObject({ done: true, busy: false, result: 2 });
    s.dispose();
  });
});

describe('failures, as a run reports them', () => {
  test('a runaway loop ends with the run\'s budget error, at the same budget', () => {
    const f = debugFn('spin', [], ['var i;', '#s1', 'i = 0;', '#s2', 'while (true) {', '  #s3', '  i++;', '  #s2', '}']);
    const v = new Stepper({ fn: f, args: [], budget: 10_000 }).continue();
    const run = createInterpreterSandbox([f]).call(0, [], 10_000);
    expect(run.ok).toBe(false);
    expect(v).toMatchObject({ done: true, error: { kind: 'budget', message: `Error in function "spin" (layer "L"): ${!run.ok && run.message}` } });
    expect(v.error!.message).toContain('steps without finishing');
    expect(['s2', 's3']).toContain(v.error!.blockId);
  });

  test('the budget is counted without the markers: exactly the run\'s steps are enough', () => {
    const f = debugFn('sum', ['n'], ['var t, i;', '#a', 't = 0;', '#b', 'for (i = 0; i < n; i++) {', '  #c', '  t += i;', '  #b', '}', '#d', 'return t;']);
    const run = createInterpreterSandbox([f]).call(0, [50], 1e6);
    if (!run.ok) throw new Error(run.message);
    expect(new Stepper({ fn: f, args: [50], budget: run.steps }).continue()).toMatchObject({ done: true, result: 1225, steps: run.steps });
    const short = new Stepper({ fn: f, args: [50], budget: run.steps - 1 }).continue();
    expect(short.error?.kind).toBe('budget');
    expect(createInterpreterSandbox([f]).call(0, [50], run.steps - 1).ok).toBe(false);
  });

  test('a throw names the block that was running; changing an input is refused', () => {
    const f = debugFn('bad', ['list'], ['#a', 'var n = list.length;', '#b', 'list.push(1);', '#c', 'return n;']);
    const v = new Stepper({ fn: f, args: [Object.freeze([1, 2])], budget: 10_000 }).continue();
    expect(v.error).toMatchObject({ kind: 'mutation', blockId: 'b' });
    expect(v.error!.message).toMatch(/^Error in function "bad" \(layer "L"\): it tried to change its input "list"/);
  });

  test('a result of another type than declared is the run\'s type error, word for word', () => {
    const spec = controller([layer('L', [textFn('wrong', 'number', [], "return 'seven';"), forward()])]);
    const session = new SessionClass(world, spec, { sandbox: createInterpreterSandbox, generateBody: null });
    const record = session.step();
    const i = allFunctions(spec).findIndex((p) => p.fn.name === 'wrong');
    const v = new Stepper({ fn: session.compiled[i], args: [], budget: 10_000, output: 'number' }).continue();
    expect(v.error).toEqual({ kind: 'type', message: record.error!.message, blockId: null });
  });
});
