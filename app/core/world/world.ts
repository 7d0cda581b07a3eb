/**
 * The world: walls, goals, the plan and the robot's body, as immutable state.
 * A step returns a new state and shares every part that did not change, so the history
 * can keep every tick cheaply and "did it change?" is `!==`.
 */
import type { BodyCommand } from '../values';
import type { Point, Segment } from './geometry';
import { crossingAlong, normalizeHeading, pointAlong, ray, segmentsIntersect } from './geometry';

export interface Goal {
  readonly name: string;
  readonly x: number;
  readonly y: number;
}

export interface Pose {
  readonly x: number;
  readonly y: number;
  /** Degrees counter-clockwise from +x, in [0, 360). */
  readonly heading: number;
}

/** The robot's body properties. */
export interface Body {
  /** Longest move in one tick. */
  readonly maxSpeed: number;
  readonly whiskerLength: number;
  /** Whisker direction relative to the heading, degrees (negative is clockwise). */
  readonly whiskerAngle: number;
}

export interface Bounds {
  readonly minX: number;
  readonly minY: number;
  readonly maxX: number;
  readonly maxY: number;
}

/** A world as its file describes it (without the file's format and version fields). */
export interface WorldSpec {
  readonly name: string;
  readonly description?: string;
  readonly walls: readonly Segment[];
  readonly goals: readonly Goal[];
  readonly plan: readonly string[];
  readonly robot: Pose;
  readonly body?: Partial<Body>;
  readonly goalRadius?: number;
  readonly bounds?: Bounds;
}

export const DEFAULT_BODY: Body = Object.freeze({ maxSpeed: 1, whiskerLength: 6, whiskerAngle: -30 });
export const DEFAULT_GOAL_RADIUS = 2;

/** The crash, once it happened: when, where, and which wall. */
export interface Crash {
  readonly tick: number;
  readonly point: Point;
  readonly wall: number;
}

/** The world at the end of one tick. Every field is immutable and shared while unchanged. */
export interface WorldState {
  readonly walls: readonly Segment[];
  readonly goals: readonly Goal[];
  readonly plan: readonly string[];
  readonly robot: Pose;
  readonly body: Body;
  readonly goalRadius: number;
  readonly bounds: Bounds | null;
  /** The body's whisker touches a wall. */
  readonly whisker: boolean;
  readonly crash: Crash | null;
  /** For each plan step, the tick it was reached, or null. */
  readonly reached: readonly (number | null)[];
}

/** The whisker as a segment: from the robot, `whiskerLength` units at heading + `whiskerAngle`. */
export function whiskerSegment(robot: Pose, body: Body): Segment {
  return ray([robot.x, robot.y], robot.heading + body.whiskerAngle, body.whiskerLength);
}

/** True when the whisker segment touches any wall. */
export function senseWhisker(robot: Pose, body: Body, walls: readonly Segment[]): boolean {
  const w = whiskerSegment(robot, body);
  for (const wall of walls) if (segmentsIntersect(w, wall)) return true;
  return false;
}

/** Index of the next plan step not yet reached, or the plan's length when all are reached. */
export function nextPlanStep(state: WorldState): number {
  const i = state.reached.indexOf(null);
  return i < 0 ? state.reached.length : i;
}

/** True when every plan step has been reached in order. */
export function planComplete(state: WorldState): boolean {
  return nextPlanStep(state) === state.reached.length;
}

export function goalByName(state: Pick<WorldState, 'goals'>, name: string): Goal | undefined {
  return state.goals.find((g) => g.name === name);
}

/** Tick 0: the world as the file describes it, with its whisker sensed and goals checked. */
export function initialState(spec: WorldSpec): WorldState {
  const body: Body = Object.freeze({ ...DEFAULT_BODY, ...(spec.body ?? {}) });
  const robot: Pose = Object.freeze({ x: spec.robot.x, y: spec.robot.y, heading: normalizeHeading(spec.robot.heading) });
  const base: WorldState = {
    walls: spec.walls,
    goals: spec.goals,
    plan: spec.plan,
    robot,
    body,
    goalRadius: spec.goalRadius ?? DEFAULT_GOAL_RADIUS,
    bounds: spec.bounds ?? null,
    whisker: senseWhisker(robot, body, spec.walls),
    crash: null,
    reached: Object.freeze(spec.plan.map(() => null)),
  };
  return Object.freeze({ ...base, reached: trackPlan(base, robot, 0) });
}

/**
 * Marks plan steps reached at `tick`: the next unreached step is reached when the robot ends the
 * tick within the goal radius of its goal. One tick reaches at most one step.
 */
function trackPlan(state: Pick<WorldState, 'plan' | 'goals' | 'reached' | 'goalRadius'>, robot: Pose, tick: number): readonly (number | null)[] {
  const i = state.reached.indexOf(null);
  if (i < 0) return state.reached;
  const goal = goalByName(state, state.plan[i]);
  if (!goal) return state.reached;
  const dx = goal.x - robot.x;
  const dy = goal.y - robot.y;
  if (dx * dx + dy * dy > state.goalRadius * state.goalRadius) return state.reached;
  const reached = state.reached.slice();
  reached[i] = tick;
  return Object.freeze(reached);
}

/**
 * Applies the body command of `tick`: the new heading, the move clamped to the body's max speed,
 * the crash check against every wall, the whisker, and the plan. A crashed robot moves no more:
 * it stays where it was when its move would have crossed the wall.
 */
export function applyCommand(state: WorldState, command: BodyCommand, tick: number): WorldState {
  if (state.crash) return state;
  const heading = normalizeHeading(command.heading);
  let { dx, dy } = command;
  const length = Math.sqrt(dx * dx + dy * dy);
  // A tiny tolerance keeps unit moves computed with cos/sin (length 1 +- 1 ulp) exact.
  if (length > state.body.maxSpeed * (1 + 1e-12)) {
    dx *= state.body.maxSpeed / length;
    dy *= state.body.maxSpeed / length;
  }
  const from: Point = [state.robot.x, state.robot.y];
  const path: Segment = [from, [from[0] + dx, from[1] + dy]];
  const hit = firstCrossing(path, state.walls);
  const robot: Pose = hit
    ? Object.freeze({ x: from[0], y: from[1], heading })
    : Object.freeze({ x: path[1][0], y: path[1][1], heading });
  return Object.freeze({
    walls: state.walls,
    goals: state.goals,
    plan: state.plan,
    robot,
    body: state.body,
    goalRadius: state.goalRadius,
    bounds: state.bounds,
    whisker: senseWhisker(robot, state.body, state.walls),
    crash: hit ? Object.freeze({ tick, point: pointAlong(path, hit.t), wall: hit.wall }) : null,
    reached: trackPlan(state, robot, tick),
  });
}

function firstCrossing(path: Segment, walls: readonly Segment[]): { t: number; wall: number } | null {
  let best: { t: number; wall: number } | null = null;
  for (let i = 0; i < walls.length; i++) {
    const t = crossingAlong(path, walls[i]);
    if (t !== null && (best === null || t < best.t)) best = { t, wall: i };
  }
  return best;
}
