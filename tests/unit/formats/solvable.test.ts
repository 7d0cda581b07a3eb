/**
 * Every example world can be solved: for each plan step there is a path, from where the robot
 * is to within the goal radius of the step's goal, that crosses and touches no wall. The search
 * walks a unit lattice from the robot's start (a point robot moving at most 1 unit per tick).
 */
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { parseWorld } from '../../../app/core/formats';
import { segmentsIntersect } from '../../../app/core/world/geometry';
import type { Point, Segment } from '../../../app/core/world/geometry';
import { DEFAULT_GOAL_RADIUS } from '../../../app/core/world/world';
import type { WorldSpec } from '../../../app/core/world/world';

const EXAMPLES = join(__dirname, '../../../examples/worlds');

/** Breadth-first search on the lattice; returns the lattice point reached near `goal`, or null. */
function reach(world: WorldSpec, from: Point, goal: Point): Point | null {
  const b = world.bounds ?? { minX: -200, minY: -200, maxX: 200, maxY: 200 };
  const radius = world.goalRadius ?? DEFAULT_GOAL_RADIUS;
  const key = (p: Point) => `${p[0]},${p[1]}`;
  const seen = new Set([key(from)]);
  const queue: Point[] = [from];
  for (let i = 0; i < queue.length; i++) {
    const p = queue[i];
    if (Math.hypot(p[0] - goal[0], p[1] - goal[1]) <= radius) return p;
    for (const [dx, dy] of [[1, 0], [-1, 0], [0, 1], [0, -1]]) {
      const q: Point = [p[0] + dx, p[1] + dy];
      if (q[0] < b.minX || q[0] > b.maxX || q[1] < b.minY || q[1] > b.maxY || seen.has(key(q))) continue;
      const move: Segment = [p, q];
      if (world.walls.some((w) => segmentsIntersect(move, w))) continue;
      seen.add(key(q));
      queue.push(q);
    }
  }
  return null;
}

describe.each(readdirSync(EXAMPLES).filter((f) => f.endsWith('.world.json')))('%s', (file) => {
  it('can be solved: every plan step is reachable without touching a wall', () => {
    const r = parseWorld(readFileSync(join(EXAMPLES, file), 'utf8'), file);
    if (!r.ok) throw new Error('does not parse');
    const world = r.value;
    expect(world.plan.length).toBeGreaterThan(0);
    let at: Point = [world.robot.x, world.robot.y];
    for (const step of world.plan) {
      const goal = world.goals.find((g) => g.name === step);
      if (!goal) throw new Error(`no goal ${step}`);
      const next = reach(world, at, [goal.x, goal.y]);
      if (!next) throw new Error(`${file}: no path to "${step}" from (${at[0]}, ${at[1]})`);
      at = next;
    }
  });
});
