/** Turns the engine's tick records into the page's small frames and world revisions. */
import type { TickRecord } from '../../core/session/types';
import type { WorldState } from '../../core/world/world';
import type { TickFrame, WorldParts } from './protocol';

/** Gives each distinct (walls, goals, plan) triple a revision number, by identity. */
export class WorldRevisions {
  private last: WorldState | null = null;
  private rev = -1;

  /** The revision of `world`, and its parts when they are new since the previous call. */
  revisionOf(world: WorldState): { rev: number; parts: WorldParts | null } {
    const l = this.last;
    if (l && l.walls === world.walls && l.goals === world.goals && l.plan === world.plan && l.body === world.body) {
      return { rev: this.rev, parts: null };
    }
    this.last = world;
    this.rev += 1;
    const parts: WorldParts = {
      rev: this.rev,
      walls: world.walls,
      goals: world.goals,
      plan: world.plan,
      body: world.body,
      goalRadius: world.goalRadius,
      bounds: world.bounds,
    };
    return { rev: this.rev, parts };
  }
}

export function frameOf(record: TickRecord, worldRev: number): TickFrame {
  const w = record.world;
  return {
    tick: record.tick,
    x: w.robot.x,
    y: w.robot.y,
    heading: w.robot.heading,
    whisker: w.whisker,
    crash: w.crash,
    reached: w.reached,
    printed: record.printed,
    error: record.error,
    edits: record.edits,
    worldRev,
  };
}
