import { createInterpreterSandbox } from '../../../app/core/sandbox/interpreter';
import { deepFreeze } from '../../../app/core/values';
import { fn, run, valueOf } from './helpers';

describe('print', () => {
  test('prints texts as they are, other values as JSON', () => {
    const r = run(['p'], 'print("hello"); print(3); print(true); print(null); print(undefined); print(p); print({ a: [1, "x"] }); print(print); return 0;', [deepFreeze([1, 2])]);
    expect(r).toMatchObject({ ok: true, output: ['hello', '3', 'true', 'null', 'undefined', '[1,2]', '{"a":[1,"x"]}', '[function]'] });
  });

  test('each call has its own output, kept when the call fails', () => {
    const s = createInterpreterSandbox([fn('f', ['n'], 'print("n=" + n); if (n > 1) throw new Error("too big"); return n;')]);
    expect(s.call(0, [1], 1000)).toMatchObject({ ok: true, output: ['n=1'] });
    expect(s.call(0, [2], 1000)).toMatchObject({ ok: false, output: ['n=2'] });
  });
});

describe('__block', () => {
  test('the last block seen is reported with a failure', () => {
    const s = createInterpreterSandbox([fn('f', ['a'], '__block("b1"); var x = a + 1;\n__block("b2"); return x.y.z;')]);
    expect(s.call(0, [1], 1000)).toMatchObject({ ok: false, kind: 'exception', blockId: 'b2' });
  });

  test('a budget failure reports the block inside the loop', () => {
    expect(run([], '__block("init"); var i = 0; while (true) { __block("loop"); i++; }', [], 5000)).toMatchObject({ kind: 'budget', blockId: 'loop' });
  });

  test('each call starts with no block', () => {
    const s = createInterpreterSandbox([fn('f', ['a'], 'if (a) { __block("x"); } return null.y;')]);
    expect(s.call(0, [true], 1000)).toMatchObject({ blockId: 'x' });
    expect(s.call(0, [false], 1000)).toMatchObject({ blockId: null });
  });
});

describe('API helpers', () => {
  const walls = deepFreeze([
    [[0, 10], [10, 10]],
    [[10, 0], [10, 10]],
  ]);

  test('geometry helpers', () => {
    expect(valueOf(run([], 'return [distance([0, 0], [3, 4]), directionTo([0, 0], [0, 5]), normalizeAngle(270), pointAt([0, 0], 0, 2)];'))).toEqual([5, 90, -90, [2, 0]]);
  });

  test('touchesAnyWall with the walls passed as an input', () => {
    const s = createInterpreterSandbox([fn('hit', ['from', 'to', 'walls'], 'return touchesAnyWall([from, to], walls);')]);
    expect(valueOf(s.call(0, [[5, 5], [5, 15], walls], 1000))).toBe(true);
    expect(valueOf(s.call(0, [[1, 1], [2, 2], walls], 1000))).toBe(false);
  });

  test('helper results are changeable local values', () => {
    expect(valueOf(run(['goals'], 'var p = goalPosition(goals, "g"); p.push(0); return [p, goalPosition(goals, "none")];', [deepFreeze([{ name: 'g', x: 1, y: 2 }])]))).toEqual([
      [1, 2, 0],
      null,
    ]);
  });

  test('grid helpers', () => {
    const body = 'var g = makeGrid(walls, [], [5, 5], 1); var t = newGrid(g, 0); t[0][0] = 1; return [g.cols, g.rows, cellOf(g, [5, 5]), inGrid(g, [-1, 0]), t.length, t[0][0], t[1][0]];';
    const [cols, rows, cell, inside, len, a, b] = valueOf(run(['walls'], body, [walls])) as unknown[];
    expect([cols, rows, inside, len, a, b]).toEqual([12, 12, false, 12, 1, 0]);
    expect(cell).toEqual([6, 6]);
  });

  test('makeGridWithRoom leaves at least the room asked for, and one cell more, around the walls', () => {
    const body = 'var a = makeGrid(walls, [], [5, 5], 2); var b = makeGridWithRoom(walls, [], [5, 5], 2, 3); var c = makeGridWithRoom(walls, [], [5, 5], 2, 0); return [a.x0, a.cols, b.x0, b.y0, b.cols, b.rows, c.x0 === a.x0 && c.cols === a.cols];';
    expect(valueOf(run(['walls'], body, [walls]))).toEqual([-2, 7, -6, -6, 11, 11, true]);
  });

  test('cellsNearWall: the cells a wall passes through, and the cells whose centre is closer to it than a distance', () => {
    // Cells of 1 from (0, 0); the wall runs along y = 5 from x = 2 to x = 4.
    const near = (margin: number) => {
      const cells = valueOf(run([], `var g = { x0: 0, y0: 0, cell: 1, cols: 10, rows: 10 }; return cellsNearWall(g, [[2, 5], [4, 5]], ${margin});`)) as number[][];
      return cells.map((c) => c.join(',')).sort();
    };
    expect(near(0)).toEqual(['2,5', '3,5', '4,5']);
    // Centres (x + 0.5, y + 0.5): row 4 and row 5 are 0.5 from the wall, rows 3 and 6 are 1.5 away.
    expect(near(1)).toEqual(['1,4', '1,5', '2,4', '2,5', '3,4', '3,5', '4,4', '4,5'].sort());
    expect(near(1.6)).toContain('3,3');
    expect(near(1.6)).toContain('3,6');
    expect(near(1.6)).not.toContain('0,6');
  });

  test('a wrong argument gets a message naming the helper and the input', () => {
    expect(run([], 'return distance(null, [1, 2]);')).toMatchObject({
      ok: false,
      kind: 'exception',
      message: 'TypeError: distance: its input "a" should be a point [x, y], but it is null.',
    });
    expect(run([], 'return touchesAnyWall([[0, 0], [1, 1]]);')).toMatchObject({ message: expect.stringContaining('its input "walls" should be a list, but it is undefined') });
  });

  test('an error raised by a helper becomes an error inside the interpreter', () => {
    expect(run([], 'try { makeGrid([], [], [0, 0], 0); } catch (e) { return e.name + ": " + e.message; }')).toMatchObject({
      ok: true,
      value: 'RangeError: makeGrid: The cell size must be greater than 0.',
    });
  });

  test('helpers cannot be replaced', () => {
    expect(run([], 'distance = function () { return 0; }; return 1;')).toMatchObject({ ok: false, kind: 'exception' });
  });
});
