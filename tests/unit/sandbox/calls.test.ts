import { createInterpreterSandbox } from '../../../app/core/sandbox/interpreter';
import { CompileError } from '../../../app/core/sandbox/types';
import { deepFreeze } from '../../../app/core/values';
import { fn, run, single, valueOf } from './helpers';

describe('calls and results', () => {
  const sandbox = createInterpreterSandbox([
    fn('add', ['a', 'b'], 'return a + b;'),
    fn('same', ['x'], 'return x;'),
    fn('wrap', ['p', 'q'], 'return { first: p, both: [p, q], n: 1 };'),
    fn('nothing', [], 'var x = 1;'),
    fn('fact', ['n'], 'return n <= 1 ? 1 : n * fact(n - 1);'),
  ]);
  afterAll(() => sandbox.dispose());

  test('calls a function with arguments and reports its steps', () => {
    const r = sandbox.call(0, [2, 3], 1000);
    expect(r).toEqual({ ok: true, value: 5, output: [], steps: expect.any(Number) });
    expect(r.ok && r.steps).toBeGreaterThan(5);
    expect(valueOf(sandbox.call(0, ['a', 'b'], 1000))).toBe('ab');
  });

  test('the same call takes the same number of steps every time', () => {
    const steps = [1, 2, 3].map(() => {
      const r = sandbox.call(4, [10], 10_000);
      return r.ok ? r.steps : -1;
    });
    expect(new Set(steps).size).toBe(1);
  });

  test('an input returned unchanged keeps its identity', () => {
    const point = deepFreeze([1, 2]);
    expect(valueOf(sandbox.call(1, [point], 1000))).toBe(point);
  });

  test('inputs inside a new result keep their identity; the result is deeply frozen', () => {
    const p = deepFreeze({ name: 'g', x: 1, y: 2 });
    const q = deepFreeze([[0, 0], [1, 1]]);
    const v = valueOf(sandbox.call(2, [p, q], 1000)) as { first: unknown; both: unknown[]; n: number };
    expect(v).toEqual({ first: p, both: [p, q], n: 1 });
    expect(v.first).toBe(p);
    expect(v.both[1]).toBe(q);
    expect(Object.isFrozen(v)).toBe(true);
    expect(Object.isFrozen(v.both)).toBe(true);
  });

  test('a function without a return gives undefined', () => {
    const r = sandbox.call(3, [], 1000);
    expect(r.ok).toBe(true);
    expect(r.ok && r.value).toBeUndefined();
  });

  test('a function can call itself by name', () => {
    expect(valueOf(sandbox.call(4, [5], 10_000))).toBe(120);
  });

  test('missing arguments are undefined', () => {
    expect(valueOf(sandbox.call(0, [1], 1000))).toBeNaN();
  });

  test('calling a disposed sandbox or a missing function is a caller error', () => {
    const s = single([], 'return 1;');
    expect(() => s.call(1, [], 100)).toThrow(RangeError);
    s.dispose();
    expect(() => s.call(0, [], 100)).toThrow(/disposed/);
  });
});

describe('values coming back', () => {
  test('JSON-like values round-trip', () => {
    const v = valueOf(run([], 'return { a: [1, "x", true, null, -0.5], b: {}, c: [] };'));
    expect(v).toEqual({ a: [1, 'x', true, null, -0.5], b: {}, c: [] });
  });

  test('holes and undefined list entries become null; undefined fields are left out (as JSON)', () => {
    expect(valueOf(run([], 'var a = [1]; a[2] = 3; return [a, [undefined], { u: undefined, k: 1 }];'))).toEqual([[1, null, 3], [null], { k: 1 }]);
  });

  test('shared parts are converted once', () => {
    const v = valueOf(run([], 'var row = [0, 0]; return [row, row];')) as unknown[];
    expect(v[0]).toBe(v[1]);
  });

  test('a function value is refused with a clear message', () => {
    const r = run([], 'return { f: function () {} };');
    expect(r).toMatchObject({ ok: false, kind: 'exception', message: 'it returned a value that cannot be kept: it is or holds a function.' });
  });

  test('a cycle is refused', () => {
    expect(run([], 'var a = []; a.push(a); return a;')).toMatchObject({ ok: false, kind: 'exception', message: expect.stringContaining('contains itself') });
  });

  test('a regular expression is refused', () => {
    expect(run([], 'return /a/;')).toMatchObject({ ok: false, kind: 'exception', message: expect.stringContaining('regular expression') });
  });
});

describe('exceptions', () => {
  test('a runtime error is reported with its type and message', () => {
    expect(run([], 'var a = null; return a[0];')).toEqual({
      ok: false,
      kind: 'exception',
      message: "TypeError: Cannot read property '0' of null",
      output: [],
      blockId: null,
    });
  });

  test('an undefined name', () => {
    expect(run([], 'return nope + 1;')).toMatchObject({ kind: 'exception', message: 'ReferenceError: nope is not defined' });
  });

  test('thrown errors and values', () => {
    expect(run([], 'throw new Error("stop here");')).toMatchObject({ kind: 'exception', message: 'stop here' });
    expect(run([], 'throw new RangeError("too far");')).toMatchObject({ kind: 'exception', message: 'RangeError: too far' });
    expect(run([], 'throw "boom";')).toMatchObject({ kind: 'exception', message: 'it threw boom' });
  });

  test('an exception caught by the code is not a failure', () => {
    expect(valueOf(run([], 'try { null.x; } catch (e) { return e.name; }'))).toBe('TypeError');
  });

  test('the interpreter works normally after an exception', () => {
    const s = createInterpreterSandbox([fn('bad', [], 'return null.x;'), fn('good', ['a'], 'return a * 2;')]);
    expect(s.call(0, [], 1000).ok).toBe(false);
    expect(valueOf(s.call(1, [21], 1000))).toBe(42);
    expect(s.call(0, [], 1000).ok).toBe(false);
    expect(valueOf(s.call(1, [4], 1000))).toBe(8);
  });
});

describe('compilation', () => {
  test('a syntax error names the function and its layer', () => {
    const make = () => createInterpreterSandbox([fn('good', [], 'return 1;'), fn('broken', [], 'return (1;', 'Middle')]);
    expect(make).toThrow(CompileError);
    try {
      make();
    } catch (e) {
      const err = e as CompileError;
      expect(err.functionName).toBe('broken');
      expect(err.layerName).toBe('Middle');
      expect(err.message).toMatch(/^Error in function "broken" \(layer "Middle"\): its code has a syntax error: .*\(line 3, column \d+\)\.$/);
    }
  });

  test('ES6 syntax is a syntax error (the interpreter is ES5)', () => {
    expect(() => createInterpreterSandbox([fn('arrow', [], 'var f = (x) => x; return 1;')])).toThrow(CompileError);
  });

  test('a source that declares no function is refused', () => {
    expect(() => createInterpreterSandbox([{ name: 'f', layer: 'L', params: [], source: 'var x = 1;' }])).toThrow(/not a function declaration/);
  });

  test('functions of different layers may share a name', () => {
    const s = createInterpreterSandbox([fn('step', [], 'return 1;', 'Top'), fn('step', [], 'return 2;', 'Bottom')]);
    expect([valueOf(s.call(0, [], 100)), valueOf(s.call(1, [], 100))]).toEqual([1, 2]);
  });

  test('top-level statements beside the declaration never run', () => {
    const s = createInterpreterSandbox([{ name: 'f', layer: 'L', params: [], source: 'function f() { return typeof g; }\nvar g = 1; while (true) {}' }]);
    expect(valueOf(s.call(0, [], 1000))).toBe('undefined');
  });
});
