/** Small timing helpers for the benchmark (the CLI may read the clock; the engine may not). */
import { performance } from 'node:perf_hooks';
import type { Session } from '../../core/session/session';

/** The median of some numbers. */
export function median(xs: readonly number[]): number {
  const s = [...xs].sort((a, b) => a - b);
  const m = Math.floor(s.length / 2);
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
}

/** Milliseconds one call of `f` takes. */
export function timeMs(f: () => void): number {
  const t0 = performance.now();
  f();
  return performance.now() - t0;
}

/**
 * Ticks per second of a session run over and over (reset whenever the run ends) for about
 * `seconds`, history recording on.
 */
export function ticksPerSecond(session: Session, seconds: number): number {
  let ticks = 0;
  const t0 = performance.now();
  let elapsed = 0;
  while (elapsed < seconds * 1000) {
    const summary = session.run(1_000_000);
    ticks += summary.ticks;
    if (summary.error) throw new Error(summary.error);
    session.reset();
    elapsed = performance.now() - t0;
  }
  return ticks / (elapsed / 1000);
}

/**
 * Ticks per second over `seconds`, as the median of `windows` equal stretches: a burst of other
 * work on the machine spoils one stretch, not the figure.
 */
export function medianTicksPerSecond(session: Session, seconds: number, windows = 5): number {
  return median(Array.from({ length: windows }, () => ticksPerSecond(session, seconds / windows)));
}

/** The worst time to seek a tick: read its record and every arc's value, over a spread of ticks. */
export function worstSeekMs(session: Session, samples = 300): number {
  const last = session.tick;
  let worst = 0;
  for (let i = 0; i <= samples; i++) {
    const tick = Math.round((i * last) / samples);
    worst = Math.max(
      worst,
      timeMs(() => {
        session.history.at(tick);
        session.arcs(tick);
      }),
    );
  }
  return worst;
}
