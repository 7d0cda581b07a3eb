/**
 * Grades submission files on worker threads, one per core (or `jobs`), each worker taking the
 * next file as soon as it is free. A watchdog bounds each file: a worker that takes longer than
 * `timeoutMs` (a controller too slow for its tick and step limits) or dies (out of memory) is
 * replaced, and that file gets a verdict saying why; the batch goes on.
 */
import { Worker } from 'node:worker_threads';
import type { Pack, SubmissionVerdict } from '../core/packs';
import { unreadableSubmission } from '../core/packs';
import { workerBundle } from './bundle';
import type { GradeInit, GradeReply, GradeTask } from './grade-protocol';

export interface PoolOptions {
  readonly jobs: number;
  readonly timeoutMs: number;
  readonly init: Omit<GradeInit, 'type'>;
  /** Called as each file's verdict arrives (for progress). */
  readonly onVerdict?: (index: number, verdict: SubmissionVerdict) => void;
}

/** Grades every file; resolves to the verdicts in the files' order. */
export function gradeOnWorkers(pack: Pack, files: readonly string[], options: PoolOptions): Promise<SubmissionVerdict[]> {
  const bundle = workerBundle('grade-worker');
  const verdicts: (SubmissionVerdict | undefined)[] = new Array(files.length);
  let next = 0;
  let done = 0;
  const who = (i: number) => files[i].replace(/^.*[\\/]/, '').replace(/\.(submission|controller)\.json$/i, '');

  return new Promise((resolve, reject) => {
    const finish = (index: number, verdict: SubmissionVerdict) => {
      if (verdicts[index]) return;
      verdicts[index] = verdict;
      options.onVerdict?.(index, verdict);
      if (++done === files.length) resolve(verdicts as SubmissionVerdict[]);
    };

    const start = () => {
      const worker = new Worker(bundle, { resourceLimits: { maxOldGenerationSizeMb: 2048 } });
      let current = -1;
      let timer: ReturnType<typeof setTimeout> | null = null;
      let stopped = false;

      const take = () => {
        if (next >= files.length) {
          stopped = true;
          void worker.terminate();
          return;
        }
        current = next++;
        timer = setTimeout(() => fail(`grading stopped after ${Math.round(options.timeoutMs / 1000)} s: a controller is too slow (check its loops, or raise --timeout)`), options.timeoutMs);
        worker.postMessage({ type: 'grade', index: current, file: files[current] } satisfies GradeTask);
      };

      // The file being graded gets a verdict; a fresh worker takes over the rest.
      const fail = (message: string) => {
        if (stopped) return;
        stopped = true;
        if (timer) clearTimeout(timer);
        void worker.terminate();
        if (current >= 0) finish(current, unreadableSubmission(pack, who(current), message));
        if (next < files.length) start();
      };

      worker.on('message', (msg: GradeReply) => {
        if (msg.type === 'ready') take();
        else if (msg.type === 'failed') {
          stopped = true;
          void worker.terminate();
          reject(new Error(msg.message));
        } else {
          if (timer) clearTimeout(timer);
          finish(msg.index, msg.verdict);
          current = -1;
          take();
        }
      });
      worker.on('error', (e) => fail(`grading failed: ${e.message}`));
      worker.on('exit', (code) => {
        if (!stopped) fail(`grading failed: the worker stopped (exit code ${code})`);
      });
      worker.postMessage({ type: 'init', ...options.init } satisfies GradeInit);
    };

    if (files.length === 0) return resolve([]);
    for (let i = 0; i < Math.min(options.jobs, files.length); i++) start();
  });
}
