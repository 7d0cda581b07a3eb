/**
 * Running a challenge: its controller in its world and in each variant world, through the same
 * Session the app and the CLI use, keeping what the criteria need (the path, the crash with its
 * wall, the error, the plan steps reached). One Session serves every world: it is reset.
 */
import type { ControllerSpec } from '../controller/model';
import { DEFAULT_STEP_BUDGET } from '../controller/model';
import type { SessionOptions } from '../session/session';
import { ControllerInvalidError, Session } from '../session/session';
import type { ControllerError } from '../session/types';
import type { Point, Segment } from '../world/geometry';
import type { WorldSpec } from '../world/world';
import { DEFAULT_GOAL_RADIUS } from '../world/world';
import type { Challenge } from './model';

/** What one run in one world did. */
export interface ChallengeRun {
  /** The world's name as verdicts show it: the world's name, or `variant 2 ("name")`. */
  readonly label: string;
  readonly world: WorldSpec;
  /** The tick limit the run had. */
  readonly maxTicks: number;
  /** The last tick computed. */
  readonly ticks: number;
  /** The robot's position at the end of every tick, from tick 0. */
  readonly path: readonly Point[];
  readonly crash: { readonly tick: number; readonly point: Point; readonly wall: Segment } | null;
  readonly error: ControllerError | null;
  readonly goalRadius: number;
}

/** The controller could not run at all (invalid graph, a function that does not compile). */
export interface SetupFailure {
  readonly setupError: string;
}

/** Grading's run options: the Session's, and a cap on the step budget a submission may ask for. */
export interface GradeOptions extends SessionOptions {
  /** The most steps one function call may take, whatever the controller asks (default 20,000,000). */
  readonly maxStepBudget?: number;
}

export const DEFAULT_MAX_STEP_BUDGET = 20_000_000;

/** The worlds a challenge runs in: its own, then each variant. */
export function challengeWorlds(challenge: Challenge): { world: WorldSpec; label: string }[] {
  const variants = challenge.criteria.flatMap((c) => (c.kind === 'variants' ? c.worlds : []));
  return [{ world: challenge.world, label: challenge.world.name }, ...variants.map((world, i) => ({ world, label: `variant ${i + 1} ("${world.name}")` }))];
}

/** Runs `controller` on every world of the challenge, or says why it cannot run. */
export function runChallenge(challenge: Challenge, controller: ControllerSpec, options: GradeOptions): ChallengeRun[] | SetupFailure {
  const cap = options.maxStepBudget ?? DEFAULT_MAX_STEP_BUDGET;
  // A submission cannot buy itself unbounded time by declaring a huge step budget.
  const spec: ControllerSpec = { ...controller, stepBudget: Math.min(controller.stepBudget ?? DEFAULT_STEP_BUDGET, cap) };
  const worlds = challengeWorlds(challenge);
  let session: Session;
  try {
    session = new Session(worlds[0].world, spec, options);
  } catch (e) {
    if (e instanceof ControllerInvalidError) return { setupError: e.problems.map((p) => `${p.path}: ${p.message}`).join('; ') };
    return { setupError: e instanceof Error ? e.message : String(e) };
  }
  try {
    return worlds.map(({ world, label }, i) => {
      if (i > 0) session.reset(world);
      return runOnce(session, world, label, challenge.maxTicks);
    });
  } finally {
    session.dispose();
  }
}

function runOnce(session: Session, world: WorldSpec, label: string, maxTicks: number): ChallengeRun {
  const path: Point[] = [[world.robot.x, world.robot.y]];
  for (let n = 0; n < maxTicks && session.status === 'ready'; n++) {
    const r = session.step().world.robot;
    path.push([r.x, r.y]);
  }
  const latest = session.history.latest;
  const crash = latest.world.crash;
  return {
    label,
    world,
    maxTicks,
    ticks: latest.tick,
    path,
    crash: crash ? { tick: crash.tick, point: crash.point, wall: latest.world.walls[crash.wall] } : null,
    error: latest.error,
    goalRadius: world.goalRadius ?? DEFAULT_GOAL_RADIUS,
  };
}
