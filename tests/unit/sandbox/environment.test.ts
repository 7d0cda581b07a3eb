import { createInterpreterSandbox } from '../../../app/core/sandbox/interpreter';
import { deepFreeze } from '../../../app/core/values';
import { fn, run, valueOf } from './helpers';

describe('the environment inside the sandbox', () => {
  test('slice works when the end is before the start (a library bug, fixed)', () => {
    expect(valueOf(run([], 'return [3, 1, 2].slice(2, 1);'))).toEqual([]);
    expect(valueOf(run([], 'var a = [3, 1, 2]; return [a.slice(1), a.slice(-2, -1), a.slice(5), a.slice(), a.slice(0, 10), a.slice(-10, 2)];'))).toEqual([
      [1, 2],
      [1],
      [],
      [3, 1, 2],
      [3, 1, 2],
      [3, 1],
    ]);
  });

  test('slice works on inputs and gives a changeable copy', () => {
    expect(valueOf(run(['a'], 'var b = a.slice(0, 2); b.push(9); return b;', [deepFreeze([1, 2, 3])]))).toEqual([1, 2, 9]);
  });

  test('sort works without a comparator (a library bug, fixed) and with one', () => {
    expect(valueOf(run([], 'return [3, 10, 2].sort();'))).toEqual([10, 2, 3]);
    expect(valueOf(run([], 'return [3, 10, 2].sort(function (a, b) { return a - b; });'))).toEqual([2, 3, 10]);
  });

  test('Math.random is refused with a hint', () => {
    expect(run([], 'return Math.random();')).toMatchObject({ ok: false, kind: 'exception', message: expect.stringContaining('use a random input instead') });
  });

  test('there is no clock', () => {
    expect(run([], 'return Date.now();')).toMatchObject({ kind: 'exception', message: expect.stringContaining('Date is not available') });
    expect(run([], 'return new Date();')).toMatchObject({ kind: 'exception', message: expect.stringContaining('Date is not available') });
  });

  test('there are no timers', () => {
    expect(valueOf(run([], 'return [typeof setTimeout, typeof setInterval];'))).toEqual(['undefined', 'undefined']);
  });

  test('the host is out of reach', () => {
    expect(valueOf(run([], 'return [typeof process, typeof require, typeof globalThis, typeof module, typeof this];'))).toEqual([
      'undefined',
      'undefined',
      'undefined',
      'undefined',
      'undefined',
    ]);
    expect(run([], 'return Function("return process")();')).toMatchObject({ kind: 'exception', message: 'ReferenceError: process is not defined' });
    expect(run([], 'return [].constructor.constructor("return process")();')).toMatchObject({ kind: 'exception' });
  });

  test('"with" is refused', () => {
    // Strict code cannot use `with` at all; a source that is not strict gets a runtime refusal.
    const s = createInterpreterSandbox([{ name: 'f', layer: 'L', params: ['o'], source: 'function f(o) { with (o) { x = 1; } return o; }' }]);
    const o = deepFreeze({ x: 0 });
    expect(s.call(0, [o], 1000)).toMatchObject({ ok: false, kind: 'exception', message: expect.stringContaining('"with"') });
    expect(o.x).toBe(0);
  });

  test('no call can leave anything behind for the next one', () => {
    const s = createInterpreterSandbox([
      fn('patch', [], 'Math.floor = function () { return 42; };'),
      fn('proto', [], 'Array.prototype.push = null;'),
      fn('rebind', [], 'print = null;'),
      fn('global', [], 'leak = 1;'),
      fn('self', [], 'self.count = 1;'),
      fn('counter', [], 'counter.n = (counter.n || 0) + 1; return counter.n;'),
      fn('check', [], 'var a = []; a.push(1); print("ok"); return [Math.floor(1.5), a, typeof leak, typeof self.count];'),
    ]);
    expect(s.call(0, [], 1000)).toMatchObject({ ok: false, kind: 'exception', message: 'TypeError: Cannot change "floor": built-in values and functions are read-only.' });
    expect(s.call(1, [], 1000)).toMatchObject({ ok: false, kind: 'exception' });
    expect(s.call(2, [], 1000)).toMatchObject({ ok: false, kind: 'exception' });
    expect(s.call(3, [], 1000)).toMatchObject({ ok: false, kind: 'exception', message: 'ReferenceError: leak is not defined' });
    expect(s.call(4, [], 1000)).toMatchObject({ ok: false, kind: 'exception' });
    expect(s.call(5, [], 1000)).toMatchObject({ ok: false, kind: 'exception' });
    expect(s.call(5, [], 1000)).toMatchObject({ ok: false, kind: 'exception' });
    expect(s.call(6, [], 1000)).toMatchObject({ ok: true, value: [1, [1], 'undefined', 'undefined'], output: ['ok'] });
  });

  test('local variables, objects and nested functions work as usual', () => {
    const body = 'var o = { n: 1 }; o.n += 1; o.m = [1]; o.m.push(2); delete o.n; function inner(x) { return x * 3; } return [o, inner(2), JSON.stringify({ a: [1] })];';
    expect(valueOf(run([], body))).toEqual([{ m: [1, 2] }, 6, '{"a":[1]}']);
  });
});
