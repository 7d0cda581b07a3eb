import { Converter } from '../../../app/core/sandbox/convert';
import { createInterpreterSandbox } from '../../../app/core/sandbox/interpreter';
import { createInterpreter } from '../../../app/core/sandbox/setup';
import { deepFreeze } from '../../../app/core/values';
import { fn, valueOf } from './helpers';

const CHANGE = 'Inputs cannot be changed: make a copy first (the "copy list" block) and change the copy.';

describe('inputs are read-only', () => {
  const sandbox = createInterpreterSandbox([
    fn('assign', ['todo'], 'todo[0] = 5; return 1;'),
    fn('push', ['plan', 'todo'], 'todo.push(5); return 1;'),
    fn('nested', ['grid'], 'grid[1][0] = 9; return 1;'),
    fn('alias', ['walls'], 'var w = walls[0]; w.pop(); return 1;'),
    fn('field', ['goal'], 'goal.x = 3; return 1;'),
    fn('add', ['goal'], 'goal.z = 3; return 1;'),
    fn('remove', ['goal'], 'delete goal.x; return 1;'),
    fn('caught', ['todo'], 'try { todo.push(1); } catch (e) { return e.name; }'),
    fn('copy', ['todo'], 'var c = copyList(todo); c.push(4); c[0][0] = 7; return [c, todo];'),
    fn('length', ['todo'], 'todo.length = 0; return 1;'),
    fn('info', ['todo'], 'return [Object.isExtensible(todo), Array.isArray(todo), todo.length, todo.slice(1), todo.indexOf(todo[1])];'),
  ]);
  afterAll(() => sandbox.dispose());
  const todo = deepFreeze([[1, 2], [3, 4]]);

  test('assigning to an input names the input', () => {
    expect(sandbox.call(0, [todo], 1000)).toEqual({ ok: false, kind: 'mutation', message: `it tried to change its input "todo". ${CHANGE}`, output: [], blockId: null });
  });

  test.each([
    ['push (an array method)', 1, [[1], todo], 'todo'],
    ['a nested list', 2, [todo], 'grid'],
    ['a part reached through a local variable', 3, [todo], 'walls'],
    ['a field of a record', 4, [deepFreeze({ x: 1 })], 'goal'],
    ['a new field', 5, [deepFreeze({ x: 1 })], 'goal'],
    ['delete', 6, [deepFreeze({ x: 1 })], 'goal'],
    ['setting the length', 9, [todo], 'todo'],
  ])('changing an input through %s is refused', (_label, index, args, name) => {
    expect(sandbox.call(index, args, 100_000)).toMatchObject({ ok: false, kind: 'mutation', message: `it tried to change its input "${name}". ${CHANGE}` });
  });

  test('the input is unchanged afterwards, and the next call sees it intact', () => {
    expect(todo).toEqual([[1, 2], [3, 4]]);
    expect(valueOf(sandbox.call(10, [todo], 100_000))).toEqual([false, true, 2, [[3, 4]], 1]);
  });

  test('the refusal is a TypeError the code may catch', () => {
    expect(valueOf(sandbox.call(7, [todo], 100_000))).toBe('TypeError');
  });

  test('a copy can be changed; the original stays as it was', () => {
    const [copy, original] = valueOf(sandbox.call(8, [todo], 100_000)) as unknown[];
    expect(copy).toEqual([[7, 2], [3, 4], 4]);
    expect(original).toBe(todo);
  });
});

describe('input conversion', () => {
  const interpreter = createInterpreter();

  test('an unchanged (frozen) input is converted once', () => {
    const conv = new Converter(interpreter);
    const walls = deepFreeze([[[0, 0], [10, 0]], [[10, 0], [10, 10]]]);
    const p = conv.toInput(walls);
    expect(conv.toInput(walls)).toBe(p);
    // A new list sharing segments reuses their conversions.
    const more = deepFreeze([...walls, [[0, 10], [0, 0]]]);
    const q = conv.toInput(more) as { properties: Record<string, unknown> };
    expect(q.properties[0]).toBe((p as { properties: Record<string, unknown> }).properties[0]);
  });

  test('the cache forgets values unused for two generations', () => {
    const conv = new Converter(interpreter);
    const a = deepFreeze([1]);
    const p = conv.toInput(a);
    conv.rotate();
    expect(conv.toInput(a)).toBe(p); // found in the older generation, promoted
    conv.rotate();
    conv.rotate();
    expect(conv.toInput(a)).not.toBe(p);
  });

  test('unfrozen values are converted every time (they could change)', () => {
    const conv = new Converter(interpreter);
    const a = [1, 2];
    expect(conv.toInput(a)).not.toBe(conv.toInput(a));
  });

  test('a converted input leads back to the very native value', () => {
    const conv = new Converter(interpreter);
    const grid = deepFreeze([[{ a: 1 }]]);
    const p = conv.toInput(grid);
    expect(conv.toNative(p)).toBe(grid);
    expect(conv.isInput(p as never)).toBe(true);
    expect(conv.isInput(conv.toLocal([1]) as never)).toBe(false);
  });

  test('non-JSON arguments are a caller error', () => {
    const conv = new Converter(interpreter);
    expect(() => conv.toInput(() => 1)).toThrow(TypeError);
  });
});
