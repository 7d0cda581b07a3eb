/**
 * The benchmark's worker thread: the fast engine's figures, measured in one locked-down realm.
 * The plain-JavaScript baseline runs in the parent's realm, which is not locked down (see
 * plain-sandbox.ts), alternating with the replans timed here.
 */
import { setFlagsFromString, getHeapStatistics } from 'node:v8';
import { runInNewContext } from 'node:vm';
import { parentPort } from 'node:worker_threads';
import { createSesSandbox, lockdownForSandbox } from '../../core/sandbox/ses';
import type { Sandbox } from '../../core/sandbox/types';
import { Session } from '../../core/session/session';
import { bodiesFrom } from '../fast-worker-support';
import { medianTicksPerSecond, ticksPerSecond, timeMs, worstSeekMs } from './measure';
import type { BenchJob, BenchReply, BenchRequest, FastFigures } from './protocol';
import { viArguments } from './vi-setup';

// A collector to call between heap measurements (taken before lockdown freezes the realm).
setFlagsFromString('--expose-gc');
const gc = runInNewContext('gc') as () => void;
lockdownForSandbox();

let job: BenchJob | null = null;
let fast: Sandbox | null = null;

/** Times of `runs` replans of the fast sandbox on an n x n grid, after `warmup` untimed ones. */
function replans(n: number, runs: number, warmup: number): number[] {
  const sandbox = fast as Sandbox;
  const args = viArguments(n);
  for (let i = 0; i < warmup; i++) {
    const check = sandbox.call(0, args, 1e12);
    if (!check.ok) throw new Error(`valueIteration failed on a ${n} x ${n} grid: ${check.message}`);
  }
  return Array.from({ length: runs }, () => timeMs(() => sandbox.call(0, args, 1e12)));
}

function heapUsed(): number {
  for (let i = 0; i < 3; i++) gc();
  return getHeapStatistics().used_heap_size;
}

function rest(j: BenchJob): FastFigures {
  const basic = new Session(j.office, j.basicController, { sandbox: createSesSandbox, generateBody: bodiesFrom(j.basicBodies) });
  ticksPerSecond(basic, Math.min(0.3, j.seconds)); // warm up
  const basicTicksPerSecond = medianTicksPerSecond(basic, j.seconds);
  basic.dispose();

  const before = heapUsed();
  const vi = new Session(j.viWorld, j.viController, { sandbox: createSesSandbox, generateBody: bodiesFrom(j.viBodies) });
  vi.run(j.historyTicks);
  const historyBytes = heapUsed() - before;
  const index = vi.functions.findIndex((p) => p.fn.name === 'valueIteration');
  let replanCount = 0;
  for (const r of vi.history.slice(1)) if (r.outputs[index] !== vi.history.at(r.tick - 1).outputs[index]) replanCount++;
  const seekMs = worstSeekMs(vi);
  const historyTicks = vi.tick;
  vi.dispose();
  return { basicTicksPerSecond, historyBytes, historyTicks, replans: replanCount, seekMs };
}

function answer(req: BenchRequest): BenchReply {
  switch (req.type) {
    case 'setup':
      job = req.job;
      fast = createSesSandbox([req.job.vi]);
      return { type: 'ready' };
    case 'replan':
      return { type: 'replan', ms: replans(req.n, req.runs, req.warmup) };
    case 'rest':
      return { type: 'rest', figures: rest(job as BenchJob) };
  }
}

parentPort?.on('message', (req: BenchRequest) => {
  let reply: BenchReply;
  try {
    reply = answer(req);
  } catch (e) {
    reply = { type: 'failed', message: e instanceof Error ? e.message : String(e) };
  }
  parentPort?.postMessage(reply);
});
