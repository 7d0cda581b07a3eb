/**
 * The fast engine's worker thread: locks its realm down (SES), then runs Sessions with the SES
 * sandbox for the parent (fast-session.ts). Before each call it writes which function it enters
 * into the shared control block, so the parent's watchdog can name it if it has to stop the worker.
 */
import { performance } from 'node:perf_hooks';
import { parentPort } from 'node:worker_threads';
import { lockdownForSandbox } from '../core/sandbox/ses';
import { Session } from '../core/session/session';
import type { RunRequest, TickDigest, WorkerReply } from './fast-protocol';
import { CONTROL } from './fast-protocol';
import { bodiesFrom, watchedSandbox } from './fast-worker-support';

lockdownForSandbox();

function run(req: RunRequest): WorkerReply {
  const control = new Int32Array(req.control);
  let session: Session;
  try {
    session = new Session(req.world, req.controller, {
      sandbox: watchedSandbox(control),
      generateBody: bodiesFrom(req.bodies),
      ...(req.seed !== undefined ? { seed: req.seed } : {}),
    });
  } catch (e) {
    return { type: 'invalid', message: e instanceof Error ? e.message : String(e) };
  }
  const started = performance.now();
  for (let n = 0; n < req.maxTicks && session.status === 'ready'; n++) {
    control[CONTROL.tick] = session.tick + 1;
    session.step();
  }
  const seconds = (performance.now() - started) / 1000;
  const digests = req.digests ? [...session.history.slice()].map(digest) : null;
  const summary = session.summary();
  session.dispose();
  return { type: 'done', summary, digests, seconds };
}

function digest(r: ReturnType<Session['history']['at']>): TickDigest {
  const w = r.world;
  return {
    tick: r.tick,
    x: w.robot.x,
    y: w.robot.y,
    heading: w.robot.heading,
    whisker: w.whisker,
    crashed: w.crash !== null,
    outputs: r.outputs,
    printed: r.printed,
    error: r.error,
  };
}

parentPort?.on('message', (req: RunRequest) => {
  parentPort?.postMessage(run(req));
});
