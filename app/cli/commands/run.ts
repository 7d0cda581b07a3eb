/** `layerbot run CONTROLLER --world WORLD`: runs headless and reports what happened. */
import { performance } from 'node:perf_hooks';
import type { Session } from '../../core/session/session';
import type { RunSummary } from '../../core/session/types';
import { runFastSession } from '../fast-session';
import type { TickDigest } from '../fast-protocol';
import { writeFileAtomic } from '../files';
import { createSession, defaultSessionOptions, loadController, loadWorld } from '../load';

export interface RunOptions {
  readonly world: string;
  readonly ticks: number;
  readonly seed?: number;
  readonly trace?: string;
  readonly json?: boolean;
  /** 'interpreter' (the reference, JS-Interpreter) or 'fast' (SES in a worker thread). */
  readonly engine?: 'interpreter' | 'fast';
}

export interface RunReport extends RunSummary {
  readonly ticksPerSecond: number;
}

/** Runs a controller in a world; resolves to the exit code (0 ran, 1 controller error). */
export async function runCommand(controllerFile: string, opts: RunOptions, out: (s: string) => void): Promise<number> {
  const world = loadWorld(opts.world);
  const controller = loadController(controllerFile);
  if (opts.engine === 'fast') {
    const fast = await runFastSession(world, controller, { maxTicks: opts.ticks, seed: opts.seed, digests: opts.trace !== undefined });
    const summary: RunSummary = fast.summary ?? { ...stoppedSummary(world.plan), error: fast.stopped?.message ?? 'The run was stopped.' };
    const report: RunReport = { ...summary, ticksPerSecond: Math.round(summary.ticks / Math.max(fast.seconds, 1e-9)) };
    if (opts.trace && fast.digests) writeFileAtomic(opts.trace, csv(fast.digests));
    out(opts.json ? JSON.stringify(report) : describe(report, controller.name, world.name));
    return summary.error ? 1 : 0;
  }
  const session = createSession(world, controller, controllerFile, defaultSessionOptions(opts.seed));
  const started = performance.now();
  const summary = session.run(opts.ticks);
  const seconds = (performance.now() - started) / 1000;
  const report: RunReport = { ...summary, ticksPerSecond: Math.round(summary.ticks / Math.max(seconds, 1e-9)) };
  if (opts.trace) writeFileAtomic(opts.trace, traceCsv(session));
  out(opts.json ? JSON.stringify(report) : describe(report, controller.name, world.name));
  session.dispose();
  return summary.error ? 1 : 0;
}

/** The trajectory as CSV, one row per tick from tick 0, numbers at full precision. */
export function traceCsv(session: Session): string {
  return csv(
    [...session.history.slice()].map((r) => ({
      tick: r.tick,
      x: r.world.robot.x,
      y: r.world.robot.y,
      heading: r.world.robot.heading,
      whisker: r.world.whisker,
      crashed: r.world.crash !== null,
    })),
  );
}

function csv(rows: readonly Pick<TickDigest, 'tick' | 'x' | 'y' | 'heading' | 'whisker' | 'crashed'>[]): string {
  const lines = ['tick,x,y,heading,whisker,crashed', ...rows.map((r) => `${r.tick},${r.x},${r.y},${r.heading},${r.whisker},${r.crashed}`)];
  return `${lines.join('\n')}\n`;
}

function stoppedSummary(plan: readonly string[]): RunSummary {
  return { ticks: 0, crashed: false, crashTick: null, goals: plan.map((name) => ({ name, reachedTick: null })), error: null };
}

function describe(r: RunReport, controller: string, world: string): string {
  const lines = [`${controller} in ${world}: ${r.ticks} ticks (${r.ticksPerSecond.toLocaleString('en-US')} ticks/s)`];
  const width = Math.max(4, ...r.goals.map((g) => g.name.length));
  r.goals.forEach((g, i) => {
    lines.push(`  ${String(i + 1).padStart(2)}. ${g.name.padEnd(width)}  ${g.reachedTick === null ? 'not reached' : `reached at tick ${g.reachedTick}`}`);
  });
  if (r.error) lines.push(r.error);
  else if (r.crashed) lines.push(`Crashed into a wall at tick ${r.crashTick}.`);
  else if (r.goals.length > 0 && r.goals.every((g) => g.reachedTick !== null)) lines.push('Every plan step reached.');
  else lines.push(`Stopped after ${r.ticks} ticks.`);
  return lines.join('\n');
}
