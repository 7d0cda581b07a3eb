/** Equal cells of grids are kept once (intern.ts); values stay equal and frozen. */
import { CellInterner } from '../../../app/core/session/intern';
import { deepFreeze, sameValue } from '../../../app/core/values';

const grid = (n: number, cell: (r: number, c: number) => unknown[]) => deepFreeze(Array.from({ length: n }, (_, r) => Array.from({ length: n }, (_, c) => cell(r, c))));

test('equal cells of a grid become one object; the grid stays equal and frozen', () => {
  const cells = new CellInterner();
  const g = grid(20, (r) => [r, r + 1, 0]);
  const shared = cells.intern(g) as unknown[][][];
  expect(sameValue(shared, g)).toBe(true);
  expect(Object.isFrozen(shared) && Object.isFrozen(shared[3])).toBe(true);
  expect(shared[3][0]).toBe(shared[3][19]);
  // A later grid reuses the cells met before.
  const again = cells.intern(grid(20, (r) => [r, r + 1, 0])) as unknown[][][];
  expect(again[5][2]).toBe(shared[5][7]);
});

test('cells that an equal-looking cell could be told from are not shared', () => {
  const cells = new CellInterner();
  const g = cells.intern(grid(16, (_r, c) => (c % 2 ? [-0, 1] : [0, 1]))) as unknown[][][];
  expect(Object.is(g[0][1][0], -0)).toBe(true);
  expect(g[0][1]).not.toBe(g[0][3]);
  const n = cells.intern(grid(16, () => [NaN])) as unknown[][][];
  expect(n[0][0]).not.toBe(n[0][1]);
  const mixed = cells.intern(grid(16, (_r, c) => (c % 2 ? [1] : ['1']))) as unknown[][][];
  expect(mixed[0][0]).not.toBe(mixed[0][1]);
  expect(mixed[0][0]).toBe(mixed[0][2]);
});

test('short lists and lone points are left as they are', () => {
  const cells = new CellInterner();
  const p = deepFreeze([[1, 2], [1, 2]]);
  expect(cells.intern(p)).toBe(p);
  const q = deepFreeze([3, 4]);
  expect(cells.intern(q)).toBe(q);
});
