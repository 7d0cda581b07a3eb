/**
 * Edits to a world: the same operations serve the Create tools (on a WorldSpec) and the drags a
 * user makes while the robot runs (on a WorldState, recorded at their tick).
 */
import type { Point, Segment } from './geometry';
import { normalizeHeading } from './geometry';
import type { Goal, Pose, WorldSpec, WorldState } from './world';
import { senseWhisker } from './world';

export type WorldEdit =
  | { readonly type: 'moveRobot'; readonly x: number; readonly y: number; readonly heading?: number }
  | { readonly type: 'addWall'; readonly wall: Segment }
  | { readonly type: 'setWall'; readonly index: number; readonly wall: Segment }
  | { readonly type: 'removeWall'; readonly index: number }
  | { readonly type: 'addGoal'; readonly goal: Goal }
  | { readonly type: 'setGoal'; readonly name: string; readonly goal: Goal }
  | { readonly type: 'removeGoal'; readonly name: string }
  | { readonly type: 'setPlan'; readonly plan: readonly string[] };

type Parts = Pick<WorldSpec, 'walls' | 'goals' | 'plan'> & { robot: Pose };

/** Applies an edit to the editable parts of a world; throws a RangeError naming what is wrong. */
function applyToParts<T extends Parts>(w: T, edit: WorldEdit): T {
  switch (edit.type) {
    case 'moveRobot':
      return { ...w, robot: Object.freeze({ x: edit.x, y: edit.y, heading: normalizeHeading(edit.heading ?? w.robot.heading) }) };
    case 'addWall':
      return { ...w, walls: Object.freeze([...w.walls, freezeSegment(edit.wall)]) };
    case 'setWall':
      checkIndex(w.walls, edit.index);
      return { ...w, walls: Object.freeze(w.walls.map((s, i) => (i === edit.index ? freezeSegment(edit.wall) : s))) };
    case 'removeWall':
      checkIndex(w.walls, edit.index);
      return { ...w, walls: Object.freeze(w.walls.filter((_s, i) => i !== edit.index)) };
    case 'addGoal':
      if (w.goals.some((g) => g.name === edit.goal.name)) throw new RangeError(`There is already a goal named "${edit.goal.name}".`);
      return { ...w, goals: Object.freeze([...w.goals, Object.freeze({ ...edit.goal })]) };
    case 'setGoal': {
      const i = w.goals.findIndex((g) => g.name === edit.name);
      if (i < 0) throw new RangeError(`There is no goal named "${edit.name}".`);
      if (edit.goal.name !== edit.name && w.goals.some((g) => g.name === edit.goal.name)) {
        throw new RangeError(`There is already a goal named "${edit.goal.name}".`);
      }
      const goals = Object.freeze(w.goals.map((g, j) => (j === i ? Object.freeze({ ...edit.goal }) : g)));
      const plan = edit.goal.name === edit.name ? w.plan : Object.freeze(w.plan.map((p) => (p === edit.name ? edit.goal.name : p)));
      return { ...w, goals, plan };
    }
    case 'removeGoal':
      if (!w.goals.some((g) => g.name === edit.name)) throw new RangeError(`There is no goal named "${edit.name}".`);
      return {
        ...w,
        goals: Object.freeze(w.goals.filter((g) => g.name !== edit.name)),
        plan: Object.freeze(w.plan.filter((p) => p !== edit.name)),
      };
    case 'setPlan':
      for (const p of edit.plan) {
        if (!w.goals.some((g) => g.name === p)) throw new RangeError(`The plan names "${p}", but there is no goal by that name.`);
      }
      return { ...w, plan: Object.freeze([...edit.plan]) };
  }
}

function checkIndex(list: readonly unknown[], index: number): void {
  if (!Number.isInteger(index) || index < 0 || index >= list.length) throw new RangeError(`There is no wall number ${index}.`);
}

function freezeSegment(s: Segment): Segment {
  return Object.freeze([Object.freeze([s[0][0], s[0][1]]) as Point, Object.freeze([s[1][0], s[1][1]]) as Point]) as Segment;
}

/** Applies an edit to a world file's model (the Create tools). */
export function editSpec(spec: WorldSpec, edit: WorldEdit): WorldSpec {
  return applyToParts(spec, edit);
}

/**
 * Applies an edit to the running world (a drag while the robot runs). The whisker is sensed
 * again; a changed plan starts its tracking over from the current tick.
 */
export function editState(state: WorldState, edit: WorldEdit): WorldState {
  const next = applyToParts(state, edit);
  const reached = next.plan === state.plan ? state.reached : Object.freeze(next.plan.map(() => null));
  return Object.freeze({ ...next, reached, whisker: senseWhisker(next.robot, next.body, next.walls) });
}
