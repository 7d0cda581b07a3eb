/** A session's trajectory as rows, for comparing runs with each other and with reference traces. */
import type { Session } from '../../app/core/session/session';

export interface TraceRow {
  readonly tick: number;
  readonly x: number;
  readonly y: number;
  readonly heading: number;
  readonly whisker: boolean;
  readonly crashed: boolean;
}

export function traceRows(session: Session): TraceRow[] {
  return [...session.history.slice()].map((r) => ({
    tick: r.tick,
    x: r.world.robot.x,
    y: r.world.robot.y,
    heading: r.world.robot.heading,
    whisker: r.world.whisker,
    crashed: r.world.crash !== null,
  }));
}

/** Reads a CSV trace (`tick,x,y,heading,whisker,crashed`). */
export function parseTrace(csv: string): TraceRow[] {
  return csv
    .trim()
    .split('\n')
    .slice(1)
    .map((line) => {
      const [tick, x, y, heading, whisker, crashed] = line.split(',');
      return { tick: Number(tick), x: Number(x), y: Number(y), heading: Number(heading), whisker: whisker === 'true', crashed: crashed === 'true' };
    });
}
