/** What the world view draws at one moment: the world's parts, the robot, the plan's progress. */
import type { Body, Crash, Goal } from '../../core/world/world';
import type { Segment } from '../../core/world/geometry';

export interface WorldPicture {
  readonly walls: readonly Segment[];
  readonly goals: readonly Goal[];
  readonly plan: readonly string[];
  readonly reached: readonly (number | null)[];
  readonly goalRadius: number;
  readonly body: Body;
  readonly robot: { readonly x: number; readonly y: number; readonly heading: number };
  readonly whisker: boolean;
  readonly crash: Crash | null;
}

/** The name of the plan's next goal (the first step not reached), or null. */
export function nextGoalName(p: Pick<WorldPicture, 'plan' | 'reached'>): string | null {
  const i = p.reached.indexOf(null);
  return i < 0 ? null : (p.plan[i] ?? null);
}
