/**
 * Runs a controller with the fast (SES) engine in a worker thread, guarded by a watchdog.
 *
 * The SES engine locks its realm down, so it lives in its own worker (fast-worker.ts). Its guards
 * stop loops and recursion, but not a slow native built-in (a catastrophic regular expression, a
 * huge `repeat`); the worker writes which function it enters into a shared control block, and when
 * one call runs longer than the limit, the parent terminates the worker and reports an error naming
 * that function. Running out of memory kills only the worker, and is reported the same way.
 */
import { performance } from 'node:perf_hooks';
import { Worker } from 'node:worker_threads';
import { generateBody } from '../../blocks/generate';
import type { GeneratedBody } from '../core/controller/compile';
import { bodyOf } from '../core/controller/compile';
import type { ControllerSpec } from '../core/controller/model';
import { allFunctions } from '../core/controller/model';
import { functionErrorMessage } from '../core/sandbox/types';
import type { ControllerError, RunSummary } from '../core/session/types';
import type { WorldSpec } from '../core/world/world';
import { workerBundle } from './bundle';
import type { RunRequest, TickDigest, WorkerReply } from './fast-protocol';
import { CONTROL } from './fast-protocol';

export interface FastRunOptions {
  readonly maxTicks: number;
  readonly seed?: number;
  /** Return every tick's digest (for comparisons) as well as the summary. */
  readonly digests?: boolean;
  /** The longest one function call may run before the watchdog stops it (default 5 s). */
  readonly callLimitMs?: number;
  /** The worker's heap limit (default 2048 MB). */
  readonly memoryMb?: number;
}

export interface FastRunResult {
  /** The run's summary; null when the watchdog stopped the worker. */
  readonly summary: RunSummary | null;
  readonly digests: readonly TickDigest[] | null;
  /** Set when the watchdog stopped the worker (too slow, or out of memory). */
  readonly stopped: ControllerError | null;
  /** Time spent computing ticks in the worker. */
  readonly seconds: number;
}

/** A controller that cannot run (invalid, or a function that does not compile). */
export class FastSetupError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'FastSetupError';
  }
}

/** The generated bodies of a controller's blocks functions, by function name. */
export function generatedBodies(controller: ControllerSpec): Record<string, GeneratedBody> {
  const bodies: Record<string, GeneratedBody> = {};
  for (const { fn, layer } of allFunctions(controller)) if (fn.body.kind === 'blocks') bodies[fn.name] = bodyOf(fn, layer, generateBody);
  return bodies;
}

/** Runs `controller` in `world` with the fast engine in a fresh worker thread. */
export function runFastSession(world: WorldSpec, controller: ControllerSpec, options: FastRunOptions): Promise<FastRunResult> {
  const control = new SharedArrayBuffer(CONTROL.size * Int32Array.BYTES_PER_ELEMENT);
  const view = new Int32Array(control);
  const request: RunRequest = {
    type: 'run',
    world,
    controller,
    bodies: generatedBodies(controller),
    maxTicks: options.maxTicks,
    ...(options.seed !== undefined ? { seed: options.seed } : {}),
    digests: options.digests ?? false,
    control,
  };
  const limitMs = options.callLimitMs ?? 5000;
  const worker = new Worker(workerBundle('fast-worker'), {
    resourceLimits: { maxOldGenerationSizeMb: options.memoryMb ?? 2048 },
  });
  const functions = allFunctions(controller);

  /** The error for a worker stopped while function number `running - 1` ran. */
  const stoppedError = (what: string): ControllerError => {
    const running = Atomics.load(view, CONTROL.running);
    const placed = running > 0 ? functions[running - 1] : undefined;
    return {
      tick: Atomics.load(view, CONTROL.tick),
      function: placed?.fn.name ?? null,
      layer: placed?.layer.name ?? null,
      blockId: null,
      kind: 'resources',
      message: placed ? functionErrorMessage(placed.fn.name, placed.layer.name, what) : `Error: ${what}`,
    };
  };

  return new Promise<FastRunResult>((resolve, reject) => {
    let settled = false;
    const finish = (f: () => void): void => {
      if (settled) return;
      settled = true;
      clearInterval(timer);
      void worker.terminate();
      f();
    };
    // The watchdog: a call is stuck when the same call has been running for longer than the limit.
    let seenCalls = -1;
    let since = performance.now();
    const timer = setInterval(
      () => {
        const calls = Atomics.load(view, CONTROL.calls);
        const running = Atomics.load(view, CONTROL.running);
        if (running === 0 || calls !== seenCalls) {
          seenCalls = calls;
          since = performance.now();
          return;
        }
        if (performance.now() - since > limitMs) {
          const seconds = limitMs / 1000;
          const stopped = stoppedError(
            `it ran for more than ${seconds} second${seconds === 1 ? '' : 's'} in one tick and was stopped. ` +
              'The step budget cannot stop a slow built-in operation: look for a regular expression that backtracks a lot, or a huge text or list.',
          );
          finish(() => resolve({ summary: null, digests: null, stopped, seconds: 0 }));
        }
      },
      Math.max(5, Math.min(100, limitMs / 4)),
    );
    worker.on('message', (reply: WorkerReply) => {
      if (reply.type === 'invalid') finish(() => reject(new FastSetupError(reply.message)));
      else finish(() => resolve({ summary: reply.summary, digests: reply.digests, stopped: null, seconds: reply.seconds }));
    });
    worker.on('error', (e: Error & { code?: string }) => {
      if (e.code === 'ERR_WORKER_OUT_OF_MEMORY') {
        const stopped = stoppedError('it needed more memory than a function may use, and was stopped.');
        finish(() => resolve({ summary: null, digests: null, stopped, seconds: 0 }));
      } else finish(() => reject(e));
    });
    worker.on('exit', (code) => finish(() => reject(new Error(`The fast engine's worker stopped unexpectedly (exit code ${code}).`))));
    worker.postMessage(request);
  });
}
