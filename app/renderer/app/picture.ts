/** Builds the world view's picture from a world spec (Create) or a recorded frame (Solve), with a draft edit. */
import type { WorldEdit } from '../../core/world/edits';
import { editSpec } from '../../core/world/edits';
import type { Bounds, WorldSpec } from '../../core/world/world';
import { DEFAULT_BODY, DEFAULT_GOAL_RADIUS, senseWhisker } from '../../core/world/world';
import type { TickFrame, WorldParts } from '../engine/protocol';
import type { WorldPicture } from '../world-view/picture';

const noneReached = new WeakMap<readonly string[], readonly null[]>();

function unreached(plan: readonly string[]): readonly null[] {
  let r = noneReached.get(plan);
  if (!r) {
    r = plan.map(() => null);
    noneReached.set(plan, r);
  }
  return r;
}

/** Applies a draft edit, or returns the spec unchanged when the edit does not apply. */
export function withDraft(spec: WorldSpec, draft: WorldEdit | null): WorldSpec {
  if (!draft) return spec;
  try {
    return editSpec(spec, draft);
  } catch {
    return spec;
  }
}

export function pictureOfSpec(spec: WorldSpec): WorldPicture {
  const body = { ...DEFAULT_BODY, ...(spec.body ?? {}) };
  return {
    walls: spec.walls,
    goals: spec.goals,
    plan: spec.plan,
    reached: unreached(spec.plan),
    goalRadius: spec.goalRadius ?? DEFAULT_GOAL_RADIUS,
    body,
    robot: spec.robot,
    whisker: senseWhisker(spec.robot, body, spec.walls),
    crash: null,
  };
}

export function pictureOfFrame(frame: TickFrame, parts: WorldParts, draft: WorldEdit | null): WorldPicture {
  let { walls, goals } = parts;
  let robot = { x: frame.x, y: frame.y, heading: frame.heading };
  let whisker = frame.whisker;
  if (draft) {
    const spec = withDraft({ name: '', walls, goals, plan: parts.plan, robot }, draft);
    walls = spec.walls;
    goals = spec.goals;
    robot = { ...spec.robot };
    whisker = senseWhisker(robot, parts.body, walls);
  }
  return { walls, goals, plan: parts.plan, reached: frame.reached, goalRadius: parts.goalRadius, body: parts.body, robot, whisker, crash: frame.crash };
}

/** The box to fit: the world's bounds joined with everything in it. */
export function boundsOf(spec: Pick<WorldSpec, 'walls' | 'goals' | 'robot' | 'bounds'>): Bounds {
  const xs = [spec.robot.x, ...spec.goals.map((g) => g.x), ...spec.walls.flatMap((w) => [w[0][0], w[1][0]])];
  const ys = [spec.robot.y, ...spec.goals.map((g) => g.y), ...spec.walls.flatMap((w) => [w[0][1], w[1][1]])];
  if (spec.bounds) {
    xs.push(spec.bounds.minX, spec.bounds.maxX);
    ys.push(spec.bounds.minY, spec.bounds.maxY);
  }
  const pad = spec.bounds ? 0 : 8;
  return { minX: Math.min(...xs) - pad, minY: Math.min(...ys) - pad, maxX: Math.max(...xs) + pad, maxY: Math.max(...ys) + pad };
}
