/**
 * The benchmark's worker thread: the fast engine's figures, measured in one locked-down realm, with
 * the plain-JavaScript baseline run in the same realm on the same generated code.
 */
import { setFlagsFromString, getHeapStatistics } from 'node:v8';
import { runInNewContext } from 'node:vm';
import { parentPort } from 'node:worker_threads';
import { createSesSandbox, lockdownForSandbox } from '../../core/sandbox/ses';
import type { Sandbox } from '../../core/sandbox/types';
import { Session } from '../../core/session/session';
import { createPlainSandbox } from './plain-sandbox';
import { bodiesFrom } from '../fast-worker-support';
import { median, ticksPerSecond, timeMs, worstSeekMs } from './measure';
import type { BenchJob, FastFigures } from './protocol';
import { VI_SIZES } from './protocol';
import { viArguments } from './vi-setup';

// A collector to call between heap measurements (taken before lockdown freezes the realm).
setFlagsFromString('--expose-gc');
const gc = runInNewContext('gc') as () => void;
lockdownForSandbox();

/** Median replan time of `sandbox`'s function 0 on an n x n grid. */
function replanMs(sandbox: Sandbox, n: number, runs: number): number {
  const args = viArguments(n);
  const check = sandbox.call(0, args, 1e12);
  if (!check.ok) throw new Error(`valueIteration failed on a ${n} x ${n} grid: ${check.message}`);
  return median(Array.from({ length: runs }, () => timeMs(() => sandbox.call(0, args, 1e12))));
}

function heapUsed(): number {
  for (let i = 0; i < 3; i++) gc();
  return getHeapStatistics().used_heap_size;
}

function measure(job: BenchJob): FastFigures {
  const fast = createSesSandbox([job.vi]);
  const plain = createPlainSandbox([job.vi]);
  const viReplanMs: Record<string, number> = {};
  const viPlainMs: Record<string, number> = {};
  for (const n of VI_SIZES) {
    const runs = n >= 150 ? 5 : 9;
    // Alternate the engines so that neither is favoured by the machine's mood.
    const f: number[] = [];
    const p: number[] = [];
    for (let i = 0; i < 3; i++) {
      p.push(replanMs(plain, n, runs));
      f.push(replanMs(fast, n, runs));
    }
    viReplanMs[n] = median(f);
    viPlainMs[n] = median(p);
  }

  const basic = new Session(job.office, job.basicController, { sandbox: createSesSandbox, generateBody: bodiesFrom(job.basicBodies) });
  ticksPerSecond(basic, Math.min(0.2, job.seconds)); // warm up
  const basicTicksPerSecond = ticksPerSecond(basic, job.seconds);
  basic.dispose();

  const before = heapUsed();
  const vi = new Session(job.viWorld, job.viController, { sandbox: createSesSandbox, generateBody: bodiesFrom(job.viBodies) });
  vi.run(job.historyTicks);
  const historyBytes = heapUsed() - before;
  const index = vi.functions.findIndex((p) => p.fn.name === 'valueIteration');
  let replans = 0;
  for (const r of vi.history.slice(1)) if (r.outputs[index] !== vi.history.at(r.tick - 1).outputs[index]) replans++;
  const seekMs = worstSeekMs(vi);
  const historyTicks = vi.tick;
  vi.dispose();
  return { viReplanMs, viPlainMs, basicTicksPerSecond, historyBytes, historyTicks, replans, seekMs };
}

parentPort?.on('message', (job: BenchJob) => {
  parentPort?.postMessage(measure(job));
});
