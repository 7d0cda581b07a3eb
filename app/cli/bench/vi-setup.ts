/**
 * What the benchmark runs value iteration on: synthetic n x n grids for single replans, and a world
 * whose value-iteration grid is 150 x 150 cells for a long run.
 */
import type { ControllerSpec } from '../../core/controller/model';
import { deepFreeze } from '../../core/values';
import type { WorldSpec } from '../../core/world/world';

/**
 * The arguments of the example's `valueIteration(previousQValues, hasWall, hasGoal, todoChanged,
 * grid)` on an n x n grid: two long walls make the values flow round an S, as in the robot trap.
 */
export function viArguments(n: number): readonly unknown[] {
  const hasWall = Array.from({ length: n }, () => new Array<boolean>(n).fill(false));
  const a = Math.floor(n / 3);
  const b = Math.floor((2 * n) / 3);
  for (let r = 0; r < b; r++) hasWall[r][a] = true;
  for (let r = n - 1; r > n - 1 - b; r--) hasWall[r][b] = true;
  const hasGoal = Array.from({ length: n }, () => new Array<boolean>(n).fill(false));
  hasGoal[Math.floor(n / 2)][n - 2] = true;
  const grid = { x0: 0, y0: 0, cell: 1, cols: n, rows: n };
  return deepFreeze([[], hasWall, hasGoal, true, grid]);
}

/** Side of the long-run world: with 4-unit cells and a one-cell margin, a 150 x 150 grid. */
const SIDE = 592;

/**
 * A square hall with two inner walls and four goals near its corners; the plan goes round them
 * fifty times, so the robot is still busy after 10,000 ticks and replans at every goal.
 */
export function viBenchWorld(): WorldSpec {
  const goals = [
    { name: 'a', x: 102, y: 102 },
    { name: 'b', x: 490, y: 490 },
    { name: 'c', x: 490, y: 102 },
    { name: 'd', x: 102, y: 490 },
  ];
  return {
    name: 'Value-iteration benchmark hall',
    walls: [
      [[0, 0], [SIDE, 0]],
      [[SIDE, 0], [SIDE, SIDE]],
      [[SIDE, SIDE], [0, SIDE]],
      [[0, SIDE], [0, 0]],
      [[200, 0], [200, 380]],
      [[400, SIDE], [400, 212]],
    ],
    goals,
    plan: Array.from({ length: 50 }, () => goals.map((g) => g.name)).flat(),
    robot: { x: 50, y: 50, heading: 90 },
  };
}

/** The controller with its grid's cell size set and a step budget large enough for big grids. */
export function withCellSize(controller: ControllerSpec, cellSize: number): ControllerSpec {
  return {
    ...controller,
    stepBudget: 1e12,
    layers: controller.layers.map((l) => ({
      ...l,
      variables: l.variables.map((v) => (v.name === 'CELL_SIZE' ? { ...v, value: cellSize } : v)),
    })),
  };
}
