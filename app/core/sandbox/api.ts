/**
 * The one table of native helpers that student code may call. The same table feeds the block
 * generators (reserved words, block definitions), the sandbox bindings and the documentation.
 * Helpers are pure functions of native values: they never see the interpreter, the world or time.
 */
import type { Point, Segment } from '../world/geometry';
import { directionTo, distance, normalizeAngle, normalizeHeading, ray, segmentsIntersect, toDegrees, toRadians } from '../world/geometry';
import type { ValueType } from '../values';

export type ApiCategory = 'geometry' | 'world' | 'grid' | 'list' | 'output';

export interface ApiParam {
  readonly name: string;
  readonly type: ValueType;
}

export interface ApiEntry {
  readonly category: ApiCategory;
  readonly params: readonly ApiParam[];
  /** The result type, or null when the helper returns nothing. */
  readonly returns: ValueType | null;
  /** One sentence a beginner understands; shown as the block's tooltip. */
  readonly doc: string;
  readonly fn: (...args: never[]) => unknown;
}

/** A grid laid over the world: `cols` x `rows` square cells of side `cell`, from (x0, y0). */
export interface GridSpec {
  readonly x0: number;
  readonly y0: number;
  readonly cell: number;
  readonly cols: number;
  readonly rows: number;
}

const p = (name: string, type: ValueType): ApiParam => ({ name, type });

/**
 * A list of n entries made by `entry`, built by appending: V8 keeps such a list "packed", where
 * `new Array(n)` makes a "holey" one, whose every read costs about ten times more once SES's
 * `lockdown()` has frozen the array prototypes (the fast engine's realm).
 */
function packed<T>(n: number, entry: () => T): T[] {
  const a: T[] = [];
  for (let i = 0; i < n; i++) a.push(entry());
  return a;
}

function gridOf(x0: number, y0: number, x1: number, y1: number, cell: number): GridSpec {
  if (!(cell > 0)) throw new RangeError('The cell size must be greater than 0.');
  const cols = Math.max(1, Math.ceil((x1 - x0) / cell));
  const rows = Math.max(1, Math.ceil((y1 - y0) / cell));
  if (cols * rows > 4_000_000) throw new RangeError(`A grid of ${cols} x ${rows} cells is too large; use a bigger cell size.`);
  return { x0, y0, cell, cols, rows };
}

/** A grid over the walls, goals and robot, with `room` units and one cell more around them. */
function gridAround(walls: readonly Segment[], goals: readonly { x: number; y: number }[], robot: Point, cell: number, room: number): GridSpec {
  const xs = [robot[0], ...goals.map((g) => g.x), ...walls.flatMap((w) => [w[0][0], w[1][0]])];
  const ys = [robot[1], ...goals.map((g) => g.y), ...walls.flatMap((w) => [w[0][1], w[1][1]])];
  const x0 = Math.floor((Math.min(...xs) - room) / cell - 1) * cell;
  const y0 = Math.floor((Math.min(...ys) - room) / cell - 1) * cell;
  return gridOf(x0, y0, Math.max(...xs) + room + cell, Math.max(...ys) + room + cell, cell);
}

/** The cell [col, row] that holds a point (it may lie outside the grid). */
function cellOf(grid: GridSpec, point: Point): [number, number] {
  return [Math.floor((point[0] - grid.x0) / grid.cell), Math.floor((point[1] - grid.y0) / grid.cell)];
}

function inGrid(grid: GridSpec, cell: readonly number[]): boolean {
  return cell[0] >= 0 && cell[1] >= 0 && cell[0] < grid.cols && cell[1] < grid.rows;
}

/** Every cell a segment passes through, found by sampling it at a quarter of the cell size. */
function cellsOfSegment(grid: GridSpec, s: Segment): [number, number][] {
  const steps = Math.max(1, Math.ceil(Math.hypot(s[1][0] - s[0][0], s[1][1] - s[0][1]) / (grid.cell / 4)));
  const seen = new Set<number>();
  const out: [number, number][] = [];
  for (let i = 0; i <= steps; i++) {
    const t = i / steps;
    const c = cellOf(grid, [s[0][0] + (s[1][0] - s[0][0]) * t, s[0][1] + (s[1][1] - s[0][1]) * t]);
    if (!inGrid(grid, c)) continue;
    const key = c[1] * grid.cols + c[0];
    if (!seen.has(key)) {
      seen.add(key);
      out.push(c);
    }
  }
  return out;
}

/** The distance from a point to the nearest point of a segment. */
function distanceToSegment(point: Point, s: Segment): number {
  const [[x0, y0], [x1, y1]] = s;
  const dx = x1 - x0;
  const dy = y1 - y0;
  const length2 = dx * dx + dy * dy;
  const t = length2 === 0 ? 0 : Math.max(0, Math.min(1, ((point[0] - x0) * dx + (point[1] - y0) * dy) / length2));
  return Math.hypot(point[0] - (x0 + t * dx), point[1] - (y0 + t * dy));
}

/** The cells a segment passes through, and every cell whose centre is closer to it than `margin`. */
function cellsNearSegment(grid: GridSpec, s: Segment, margin: number): [number, number][] {
  const out = cellsOfSegment(grid, s);
  if (!(margin > 0)) return out;
  const seen = new Set(out.map((c) => c[1] * grid.cols + c[0]));
  const [c0, r0] = cellOf(grid, [Math.min(s[0][0], s[1][0]) - margin, Math.min(s[0][1], s[1][1]) - margin]);
  const [c1, r1] = cellOf(grid, [Math.max(s[0][0], s[1][0]) + margin, Math.max(s[0][1], s[1][1]) + margin]);
  for (let r = Math.max(0, r0); r <= Math.min(grid.rows - 1, r1); r++) {
    for (let c = Math.max(0, c0); c <= Math.min(grid.cols - 1, c1); c++) {
      const centre: Point = [grid.x0 + (c + 0.5) * grid.cell, grid.y0 + (r + 0.5) * grid.cell];
      if (!seen.has(r * grid.cols + c) && distanceToSegment(centre, s) < margin) out.push([c, r]);
    }
  }
  return out;
}

/** Column and row steps of the grid actions north, east, south, west and stay. */
const NEIGHBOUR_STEPS: readonly (readonly [number, number])[] = [[0, 1], [1, 0], [0, -1], [-1, 0], [0, 0]];

/** The native helpers, by the name generated code calls them with. */
export const API = {
  distance: {
    category: 'geometry',
    params: [p('a', 'point'), p('b', 'point')],
    returns: 'number',
    doc: 'The distance between two points.',
    fn: (a: Point, b: Point) => distance(a, b),
  },
  directionTo: {
    category: 'geometry',
    params: [p('from', 'point'), p('to', 'point')],
    returns: 'number',
    doc: 'The direction from one point to another, in degrees counter-clockwise from east (0 to 360).',
    fn: (from: Point, to: Point) => directionTo(from, to),
  },
  normalizeAngle: {
    category: 'geometry',
    params: [p('degrees', 'number')],
    returns: 'number',
    doc: 'An angle brought into the range -180 (exclusive) to 180 degrees: how far to turn, left positive.',
    fn: (d: number) => normalizeAngle(d),
  },
  normalizeHeading: {
    category: 'geometry',
    params: [p('degrees', 'number')],
    returns: 'number',
    doc: 'An angle brought into the range 0 to 360 degrees.',
    fn: (d: number) => normalizeHeading(d),
  },
  toRadians: {
    category: 'geometry',
    params: [p('degrees', 'number')],
    returns: 'number',
    doc: 'Degrees to radians.',
    fn: (d: number) => toRadians(d),
  },
  toDegrees: {
    category: 'geometry',
    params: [p('radians', 'number')],
    returns: 'number',
    doc: 'Radians to degrees.',
    fn: (r: number) => toDegrees(r),
  },
  pointAt: {
    category: 'geometry',
    params: [p('from', 'point'), p('heading', 'number'), p('length', 'number')],
    returns: 'point',
    doc: 'The point at a distance from a point, in a direction (degrees).',
    fn: (from: Point, heading: number, length: number) => ray(from, heading, length)[1],
  },
  segmentsIntersect: {
    category: 'geometry',
    params: [p('a', 'list'), p('b', 'list')],
    returns: 'boolean',
    doc: 'True when two segments [[x0, y0], [x1, y1]] cross or touch (parallel segments never do).',
    fn: (a: Segment, b: Segment) => segmentsIntersect(a, b),
  },
  touchesAnyWall: {
    category: 'world',
    params: [p('segment', 'list'), p('walls', 'list')],
    returns: 'boolean',
    doc: 'True when a segment crosses or touches any of the walls.',
    fn: (s: Segment, walls: readonly Segment[]) => walls.some((w) => segmentsIntersect(s, w)),
  },
  goalPosition: {
    category: 'world',
    params: [p('goals', 'list'), p('name', 'string')],
    returns: 'point',
    doc: 'The position [x, y] of the goal with this name (null if there is none).',
    fn: (goals: readonly { name: string; x: number; y: number }[], name: string) => {
      const g = goals.find((x) => x.name === name);
      return g ? [g.x, g.y] : null;
    },
  },
  makeGrid: {
    category: 'grid',
    params: [p('walls', 'list'), p('goals', 'list'), p('robotPos', 'point'), p('cellSize', 'number')],
    returns: 'record',
    doc: 'A grid of square cells covering the walls, the goals and the robot, with a margin of one cell.',
    fn: (walls: readonly Segment[], goals: readonly { x: number; y: number }[], robot: Point, cell: number) => gridAround(walls, goals, robot, cell, 0),
  },
  makeGridWithRoom: {
    category: 'grid',
    params: [p('walls', 'list'), p('goals', 'list'), p('robotPos', 'point'), p('cellSize', 'number'), p('room', 'number')],
    returns: 'record',
    doc: 'A grid of square cells covering the walls, the goals and the robot, with at least a distance of room around them, plus one cell.',
    fn: (walls: readonly Segment[], goals: readonly { x: number; y: number }[], robot: Point, cell: number, room: number) => gridAround(walls, goals, robot, cell, room),
  },
  cellOf: {
    category: 'grid',
    params: [p('grid', 'record'), p('point', 'point')],
    returns: 'point',
    doc: 'The cell [column, row] of the grid that holds a point.',
    fn: (grid: GridSpec, point: Point) => cellOf(grid, point),
  },
  cellCenter: {
    category: 'grid',
    params: [p('grid', 'record'), p('cell', 'point')],
    returns: 'point',
    doc: 'The centre [x, y] of a grid cell [column, row].',
    fn: (grid: GridSpec, cell: Point) => [grid.x0 + (cell[0] + 0.5) * grid.cell, grid.y0 + (cell[1] + 0.5) * grid.cell],
  },
  inGrid: {
    category: 'grid',
    params: [p('grid', 'record'), p('cell', 'point')],
    returns: 'boolean',
    doc: 'True when a cell [column, row] lies inside the grid.',
    fn: (grid: GridSpec, cell: Point) => inGrid(grid, cell),
  },
  cellsOfWall: {
    category: 'grid',
    params: [p('grid', 'record'), p('wall', 'list')],
    returns: 'list',
    doc: 'Every cell [column, row] that a wall passes through.',
    fn: (grid: GridSpec, wall: Segment) => cellsOfSegment(grid, wall),
  },
  cellsNearWall: {
    category: 'grid',
    params: [p('grid', 'record'), p('wall', 'list'), p('distance', 'number')],
    returns: 'list',
    doc: 'Every cell [column, row] that a wall passes through, and every cell whose centre is closer to the wall than a distance.',
    fn: (grid: GridSpec, wall: Segment, margin: number) => cellsNearSegment(grid, wall, margin),
  },
  newGrid: {
    category: 'grid',
    params: [p('grid', 'record'), p('value', 'any')],
    returns: 'list',
    doc: 'A table with one entry per cell (a list of rows, each a list of columns), every entry set to a value.',
    fn: (grid: GridSpec, value: unknown) => packed(grid.rows, () => packed(grid.cols, () => value)),
  },
  goalNames: {
    category: 'world',
    params: [p('goals', 'list')],
    returns: 'list',
    doc: 'The names of the goals, in the order the world lists them.',
    fn: (goals: readonly { name: string }[]) => goals.map((g) => g.name),
  },
  neighbourCell: {
    category: 'grid',
    params: [p('cell', 'point'), p('action', 'number')],
    returns: 'point',
    doc: 'The cell [column, row] next to a cell in the direction of an action: 0 north, 1 east, 2 south, 3 west, 4 stay.',
    fn: (cell: Point, action: number) => {
      const [dc, dr] = NEIGHBOUR_STEPS[action] ?? [0, 0];
      return [cell[0] + dc, cell[1] + dr];
    },
  },
  listWithout: {
    category: 'list',
    params: [p('list', 'list'), p('item', 'any')],
    returns: 'list',
    doc: 'A new list with every copy of an item taken out (the original list does not change).',
    fn: (list: readonly unknown[], item: unknown) => list.filter((x) => !sameJson(x, item)),
  },
  moveToFront: {
    category: 'list',
    params: [p('list', 'list'), p('item', 'any')],
    returns: 'list',
    doc: 'A new list that starts with the item, followed by the other items of the list in their order (the original list does not change).',
    fn: (list: readonly unknown[], item: unknown) => [item, ...list.filter((x) => !sameJson(x, item))],
  },
  copyList: {
    category: 'list',
    params: [p('list', 'list')],
    returns: 'list',
    doc: 'A copy of a list that can be changed without changing the original (copies lists inside it too).',
    fn: (list: readonly unknown[]) => structuredCloneJson(list),
  },
} satisfies Record<string, ApiEntry>;

export type ApiName = keyof typeof API;

/** Names the sandbox also binds, besides the table: printing and block tracking. */
export const SPECIAL_NAMES = ['print', '__block'] as const;

/** Every name generated code may call: reserved for the generators, bound by the sandboxes. */
export const RESERVED_NAMES: readonly string[] = [...Object.keys(API), ...SPECIAL_NAMES];

function structuredCloneJson<T>(v: T): T {
  if (Array.isArray(v)) return v.map(structuredCloneJson) as T;
  if (typeof v === 'object' && v !== null) {
    const out: Record<string, unknown> = {};
    for (const [k, x] of Object.entries(v)) out[k] = structuredCloneJson(x);
    return out as T;
  }
  return v;
}

function sameJson(a: unknown, b: unknown): boolean {
  if (a === b) return true;
  if (typeof a !== 'object' || typeof b !== 'object' || a === null || b === null) return false;
  return JSON.stringify(a) === JSON.stringify(b);
}
