import { createInterpreterSandbox } from '../../../app/core/sandbox/interpreter';
import { OUTPUT_LIMITS } from '../../../app/core/sandbox/natives';
import { fn, run, valueOf } from './helpers';

describe('runaway code never hangs or crashes the host', () => {
  test('an endless loop runs out of steps; the interpreter works afterwards', () => {
    const s = createInterpreterSandbox([fn('spin', [], 'while (true) {}'), fn('ok', ['a'], 'return a + 1;')]);
    expect(s.call(0, [], 10_000)).toEqual({
      ok: false,
      kind: 'budget',
      message: 'it ran for more than 10,000 steps without finishing. Check its loops: is there one that never ends?',
      output: [],
      blockId: null,
    });
    expect(valueOf(s.call(1, [1], 1000))).toBe(2);
    expect(s.call(0, [], 5000).ok).toBe(false);
    expect(valueOf(s.call(1, [2], 1000))).toBe(3);
  });

  test('the budget is exact: a call that needs N steps passes with N and fails with N - 1', () => {
    const s = createInterpreterSandbox([fn('sum', [], 'var s = 0; for (var i = 0; i < 50; i++) s += i; return s;')]);
    const r = s.call(0, [], 100_000);
    const steps = r.ok ? r.steps : 0;
    expect(s.call(0, [], steps)).toMatchObject({ ok: true, value: 1225 });
    expect(s.call(0, [], steps - 1)).toMatchObject({ ok: false, kind: 'budget' });
  });

  test('array methods (interpreted polyfills) count their steps too', () => {
    const r = run([], 'var a = []; for (var i = 0; i < 100; i++) a.push(i); return a.map(function (x) { return x * 2; }).length;');
    expect(r).toMatchObject({ ok: true, value: 100 });
    expect(r.ok && r.steps).toBeGreaterThan(2000);
  });

  test('the budget stops a loop hidden in a try/catch', () => {
    expect(run([], 'try { while (true) {} } catch (e) { return 1; }', [], 5000)).toMatchObject({ kind: 'budget' });
  });

  test('endless recursion is stopped as "resources"; the interpreter works afterwards', () => {
    const s = createInterpreterSandbox([fn('down', ['n'], 'return down(n + 1);'), fn('depth', ['n'], 'return n === 0 ? 0 : 1 + depth(n - 1);')]);
    expect(s.call(0, [0], 10_000_000)).toMatchObject({ ok: false, kind: 'resources', message: expect.stringContaining('Check its recursion') });
    // Reasonable recursion still works.
    expect(valueOf(s.call(1, [2000], 10_000_000))).toBe(2000);
  });

  test('a recursion error cannot be caught and ignored', () => {
    expect(run([], 'function r() { return r(); } try { r(); } catch (e) { return 1; }', [], 10_000_000)).toMatchObject({ kind: 'resources' });
  });

  test('a huge list is refused when it comes back', () => {
    expect(run([], 'return new Array(1e9);')).toMatchObject({ ok: false, kind: 'resources', message: expect.stringContaining('1,000,000,000 entries') });
    expect(run([], 'var a = []; a[5e8] = 1; return [a];')).toMatchObject({ ok: false, kind: 'resources' });
  });

  test('a sparse list that stays inside is fine', () => {
    expect(valueOf(run([], 'var a = new Array(1e9); a[5e8] = 1; return a.length;'))).toBe(1e9);
  });

  test('doubling a text in a loop is stopped', () => {
    expect(run([], 'var s = "ab"; while (true) { s = s + s; }', [], 1_000_000)).toMatchObject({ ok: false, kind: 'resources', message: expect.stringContaining('text longer than') });
    expect(run([], 'var s = "ab"; while (true) { s += s; }', [], 1_000_000)).toMatchObject({ kind: 'resources' });
  });

  test('building a giant list runs out of steps', () => {
    expect(run([], 'var a = []; while (true) a.push(a.length);', [], 200_000)).toMatchObject({ kind: 'budget' });
  });

  test('a result nested too deeply is refused', () => {
    expect(run([], 'var a = []; for (var i = 0; i < 5000; i++) a = [a]; return a;', [], 1_000_000)).toMatchObject({ kind: 'resources', message: expect.stringContaining('nested') });
  });

  test('an exponentially shared result is converted in linear time', () => {
    const v = valueOf(run([], 'var a = [1]; for (var i = 0; i < 40; i++) a = [a, a]; return a;', [], 1_000_000)) as unknown[];
    expect(v[0]).toBe(v[1]);
  });

  test('printing in a loop keeps a bounded output', () => {
    const r = run([], 'while (true) print("line");', [], 200_000);
    expect(r).toMatchObject({ ok: false, kind: 'budget' });
    expect(r.output).toHaveLength(OUTPUT_LIMITS.maxLines + 1);
    expect(r.output[OUTPUT_LIMITS.maxLines]).toMatch(/the rest is not shown/);
  });
});
