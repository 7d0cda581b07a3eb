/**
 * A function called with the same inputs as on its last call is not called again (functions are
 * pure, T12): its value and printed lines are reused, so nothing a student can see changes.
 * Also: an error found outside the session (the app's watchdog) is recorded at the next tick (T9).
 */
import type { CompiledFunction, SandboxFactory } from '../../../app/core/sandbox/types';
import { Session } from '../../../app/core/session/session';
import { createPlainSandbox } from '../../../app/cli/bench/plain-sandbox';
import { controller, fn, forward, layer, world } from '../../support/controllers';

/** The plain sandbox, counting calls by function name. */
function counting(calls: Record<string, number>): SandboxFactory {
  return (functions: readonly CompiledFunction[]) => {
    const inner = createPlainSandbox(functions);
    return {
      call(index, args, budget) {
        calls[functions[index].name] = (calls[functions[index].name] ?? 0) + 1;
        return inner.call(index, args, budget);
      },
      dispose: () => inner.dispose(),
    };
  };
}

const constant = fn('label', 'string', [{ name: 'goals', from: { kind: 'world', input: 'goals' } }], 'print("thinking"); return "g" + goals.length;');
const ticking = fn('clock', 'number', [{ name: 't', from: { kind: 'world', input: 'tick' } }], 'return t * 2;');

test('a function whose inputs did not change keeps its value and printed lines without being called', () => {
  const calls: Record<string, number> = {};
  const s = new Session(world, controller([layer('Top', [constant, ticking]), layer('Bottom', [forward()])]), { sandbox: counting(calls), generateBody: null });
  s.run(5);
  expect(calls.label).toBe(1);
  expect(calls.clock).toBe(5);
  for (let t = 1; t <= 5; t++) {
    const r = s.history.at(t);
    expect(r.outputs[0]).toBe('g1');
    expect(r.outputs[1]).toBe(2 * t);
    expect(r.printed.map((l) => `${l.function}: ${l.text}`)).toEqual(['label: thinking']);
  }
});

test('after a reset every function is called again', () => {
  const calls: Record<string, number> = {};
  const s = new Session(world, controller([layer('Top', [constant]), layer('Bottom', [forward()])]), { sandbox: counting(calls), generateBody: null });
  s.run(3);
  s.reset();
  s.run(3);
  expect(calls.label).toBe(2);
});

test('an error found outside the session stops the run at the next tick, the world as it was', () => {
  const s = new Session(world, controller([layer('Bottom', [forward()])]), { sandbox: createPlainSandbox, generateBody: null });
  s.run(2);
  const r = s.stopNextTick({ function: 'changePos', layer: 'Bottom', blockId: null, kind: 'resources', message: 'Error in function "changePos" (layer "Bottom"): stopped.' });
  expect(r.tick).toBe(3);
  expect(r.error?.tick).toBe(3);
  expect(r.world).toBe(s.history.at(2).world);
  expect(s.status).toBe('error');
  expect(s.step()).toBe(r);
});
