/**
 * World files (`*.world.json`): reading with every problem explained, and writing.
 *
 * Reading goes: JSON text -> envelope (format, version, migration) -> JSON Schema -> world-level
 * checks that a schema cannot express -> the in-memory WorldSpec, deeply frozen.
 */
import type { Body, Bounds, Goal, Pose, WorldSpec } from '../world/world';
import type { Point, Segment } from '../world/geometry';
import { deepFreeze } from '../values';
import type { Result } from './types';
import { fail, ok } from './types';
import type { JsonDocument } from './json';
import { parseJsonText } from './json';
import { CURRENT_VERSION, FORMATS, openEnvelope } from './envelope';
import { closest, schemaProblems } from './validator';
import type { SchemaValidator } from './validator';
import { prettyJson } from './pretty';
import worldSchema from './schemas/world.schema.json';
import validateWorldSchema from './generated/world.validate';

/** The world file's JSON Schema (for editors, and for the app to offer). */
export const WORLD_SCHEMA: object = worldSchema;

/** Reads a world file. `fileName` only names the file in problems. */
export function parseWorld(text: string, fileName: string): Result<WorldSpec> {
  const json = parseJsonText(text, fileName);
  if (!json.ok) return json;
  const envelope = openEnvelope(json.value, 'world', fileName);
  if (!envelope.ok) return fail(envelope.problems);
  const doc: JsonDocument = { value: envelope.value, positionOf: json.value.positionOf };
  const shape = schemaProblems(validateWorldSchema as SchemaValidator, worldSchema, doc, fileName);
  const spec = shape.length ? undefined : toWorldSpec(envelope.value as unknown as WorldFile);
  // World-level checks run even on a malformed file (on its well-formed parts), so a teacher
  // sees every problem in one go rather than one layer of problems per attempt.
  const meaning = (spec ? worldProblems(spec) : checkWorld(looseWorld(envelope.value))).map((p) => {
    const at = doc.positionOf(p.path);
    return { file: fileName, ...p, ...(at ? { line: at.line, column: at.column } : {}) };
  });
  if (spec && !meaning.length) return ok(deepFreeze(spec));
  return fail([...shape, ...meaning]);
}

/** The JSON a world file holds, once its schema has checked it. */
interface WorldFile {
  name: string;
  description?: string;
  walls: [[number, number], [number, number]][];
  goals: { name: string; x: number; y: number }[];
  plan: string[];
  robot: { x: number; y: number; heading: number };
  goalRadius?: number;
  bounds?: Bounds;
  body?: Partial<Body>;
}

/** Copies exactly the model's fields, so stray values (such as `$schema`) never reach the engine. */
function toWorldSpec(f: WorldFile): WorldSpec {
  const body: Partial<Body> | undefined = f.body && {
    ...(f.body.maxSpeed !== undefined ? { maxSpeed: f.body.maxSpeed } : {}),
    ...(f.body.whiskerLength !== undefined ? { whiskerLength: f.body.whiskerLength } : {}),
    ...(f.body.whiskerAngle !== undefined ? { whiskerAngle: f.body.whiskerAngle } : {}),
  };
  return {
    name: f.name,
    ...(f.description !== undefined ? { description: f.description } : {}),
    walls: f.walls.map(([a, b]): Segment => [[a[0], a[1]], [b[0], b[1]]]),
    goals: f.goals.map((g): Goal => ({ name: g.name, x: g.x, y: g.y })),
    plan: f.plan.slice(),
    robot: { x: f.robot.x, y: f.robot.y, heading: f.robot.heading },
    ...(body ? { body } : {}),
    ...(f.goalRadius !== undefined ? { goalRadius: f.goalRadius } : {}),
    ...(f.bounds ? { bounds: { minX: f.bounds.minX, minY: f.bounds.minY, maxX: f.bounds.maxX, maxY: f.bounds.maxY } } : {}),
  };
}

/**
 * What is wrong with a world beyond its shape, each with its JSON path:
 * - two goals with the same name (the plan could not say which one it means);
 * - a plan step naming no goal (the robot could never reach it);
 * - a wall whose two ends are the same point: the textbook's intersection test never reports a
 *   crossing with it, so the robot would drive through something drawn as a wall. Rejected,
 *   rather than silently kept, because it is always a slip (a click without a drag, a copied
 *   point); the world editor should drop such walls before saving;
 * - the robot starting on a wall: every move away from it would count as a crash at once;
 * - bounds that are empty or inside out, or that leave out the robot's start or a goal (the view
 *   would hide them and grid planners would have no cell for them). Walls may reach outside.
 *
 * Exported so the world editor can show the same problems before it saves.
 */
export function worldProblems(spec: WorldSpec): { path: string; message: string }[] {
  return checkWorld({
    goals: spec.goals,
    plan: spec.plan,
    walls: spec.walls,
    robot: spec.robot,
    bounds: spec.bounds,
  });
}

/**
 * A world whose parts may be missing or malformed: readers run the world-level checks even when
 * the schema found problems, on whatever parts are well formed, so a file's every problem is
 * reported at once. Arrays keep their indices (a malformed entry is undefined) so paths stay right.
 */
interface LooseWorld {
  readonly goals: readonly ({ name: string; x?: number; y?: number } | undefined)[];
  readonly plan: readonly (string | undefined)[];
  readonly walls: readonly (Segment | undefined)[];
  readonly robot: Pose | undefined;
  readonly bounds: Bounds | undefined;
}

function checkWorld(w: LooseWorld): { path: string; message: string }[] {
  const problems: { path: string; message: string }[] = [];
  const add = (path: string, message: string) => problems.push({ path, message });

  const firstIndex = new Map<string, number>();
  w.goals.forEach((g, i) => {
    if (!g) return;
    const first = firstIndex.get(g.name);
    if (first !== undefined) add(`$.goals[${i}].name`, `two goals are named "${g.name}" ($.goals[${first}] and $.goals[${i}]); goal names must differ`);
    else firstIndex.set(g.name, i);
  });

  const names = [...firstIndex.keys()];
  w.plan.forEach((step, i) => {
    if (step === undefined || firstIndex.has(step)) return;
    const guess = closest(step, names);
    const known = names.length ? `the goals are: ${names.join(', ')}` : 'the world has no goals';
    add(`$.plan[${i}]`, `no goal is named "${step}"${guess ? ` (did you mean "${guess}"?)` : ''}; ${known}`);
  });

  w.walls.forEach((wall, i) => {
    if (!wall) return;
    if (wall[0][0] === wall[1][0] && wall[0][1] === wall[1][1]) {
      add(`$.walls[${i}]`, `this wall starts and ends at the same point (${wall[0][0]}, ${wall[0][1]}), so the robot could never touch it; move one end or remove the wall`);
    } else if (w.robot && onSegment([w.robot.x, w.robot.y], wall)) {
      add('$.robot', `the robot starts on the wall $.walls[${i}], so its first move would crash; move the robot or the wall`);
    }
  });

  const b = w.bounds;
  if (b) {
    if (!(b.minX < b.maxX)) add('$.bounds', `minX (${b.minX}) must be less than maxX (${b.maxX})`);
    if (!(b.minY < b.maxY)) add('$.bounds', `minY (${b.minY}) must be less than maxY (${b.maxY})`);
    const inside = (x: number, y: number) => x >= b.minX && x <= b.maxX && y >= b.minY && y <= b.maxY;
    if (b.minX < b.maxX && b.minY < b.maxY) {
      if (w.robot && !inside(w.robot.x, w.robot.y)) {
        add('$.robot', `the robot starts at (${w.robot.x}, ${w.robot.y}), outside the bounds; widen $.bounds or move the robot`);
      }
      w.goals.forEach((g, i) => {
        if (g && g.x !== undefined && g.y !== undefined && !inside(g.x, g.y)) {
          add(`$.goals[${i}]`, `the goal "${g.name}" at (${g.x}, ${g.y}) is outside the bounds; widen $.bounds or move the goal`);
        }
      });
    }
  }
  return problems;
}

/** The well-formed parts of a file that failed its schema, for checkWorld. */
function looseWorld(raw: Record<string, unknown>): LooseWorld {
  const list = (v: unknown): readonly unknown[] => (Array.isArray(v) ? v : []);
  const num = (v: unknown): v is number => typeof v === 'number';
  const rec = (v: unknown): Record<string, unknown> | undefined => (typeof v === 'object' && v !== null && !Array.isArray(v) ? (v as Record<string, unknown>) : undefined);
  const point = (v: unknown): Point | undefined => (Array.isArray(v) && v.length === 2 && num(v[0]) && num(v[1]) ? [v[0], v[1]] : undefined);
  const robot = rec(raw.robot);
  const bounds = rec(raw.bounds);
  return {
    goals: list(raw.goals).map((g) => {
      const r = rec(g);
      if (!r || typeof r.name !== 'string') return undefined;
      return { name: r.name, ...(num(r.x) && num(r.y) ? { x: r.x, y: r.y } : {}) };
    }),
    plan: list(raw.plan).map((p) => (typeof p === 'string' ? p : undefined)),
    walls: list(raw.walls).map((w) => {
      if (!Array.isArray(w) || w.length !== 2) return undefined;
      const a = point(w[0]);
      const b = point(w[1]);
      return a && b ? ([a, b] as Segment) : undefined;
    }),
    robot: robot && num(robot.x) && num(robot.y) ? { x: robot.x, y: robot.y, heading: 0 } : undefined,
    bounds:
      bounds && num(bounds.minX) && num(bounds.minY) && num(bounds.maxX) && num(bounds.maxY)
        ? { minX: bounds.minX, minY: bounds.minY, maxX: bounds.maxX, maxY: bounds.maxY }
        : undefined,
  };
}

/**
 * True when point p lies on segment s. (The textbook test treats a zero-length segment as
 * parallel to everything, so a point is checked directly: collinear and between the ends.)
 */
function onSegment(p: Point, s: Segment): boolean {
  const [[x0, y0], [x1, y1]] = s;
  const cross = (x1 - x0) * (p[1] - y0) - (y1 - y0) * (p[0] - x0);
  if (cross !== 0) return false;
  return p[0] >= Math.min(x0, x1) && p[0] <= Math.max(x0, x1) && p[1] >= Math.min(y0, y1) && p[1] <= Math.max(y0, y1);
}

/** A world as file text: pretty JSON, `format` and `version` first, then a fixed order of fields. */
export function serializeWorld(spec: WorldSpec): string {
  const body = spec.body && {
    maxSpeed: spec.body.maxSpeed,
    whiskerLength: spec.body.whiskerLength,
    whiskerAngle: spec.body.whiskerAngle,
  };
  return prettyJson({
    format: FORMATS.world,
    version: CURRENT_VERSION.world,
    name: spec.name,
    description: spec.description,
    bounds: spec.bounds && { minX: spec.bounds.minX, minY: spec.bounds.minY, maxX: spec.bounds.maxX, maxY: spec.bounds.maxY },
    robot: { x: spec.robot.x, y: spec.robot.y, heading: spec.robot.heading } satisfies Pose,
    body,
    goalRadius: spec.goalRadius,
    goals: spec.goals.map((g) => ({ name: g.name, x: g.x, y: g.y })),
    plan: spec.plan,
    walls: spec.walls,
  }, (path) => path === '$.walls' || path === '$.goals');
}
