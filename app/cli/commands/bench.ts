/**
 * `layerbot bench`: the performance figures of DESIGN.md section 9, measured in one run. The fast
 * engine's figures come from a worker thread (its realm is locked down), where the plain-JavaScript
 * baseline runs too, on the same generated code; the reference engine's from this thread.
 */
import { join } from 'node:path';
import { Worker } from 'node:worker_threads';
import { generateBody } from '../../../blocks/generate';
import { compileController } from '../../core/controller/compile';
import { createInterpreterSandbox } from '../../core/sandbox/interpreter';
import { Session } from '../../core/session/session';
import { ticksPerSecond } from '../bench/measure';
import type { BenchJob, FastFigures } from '../bench/protocol';
import { RATIO_SIZE, VI_SIZES } from '../bench/protocol';
import { viBenchWorld, withCellSize } from '../bench/vi-setup';
import { repositoryRoot, workerBundle } from '../bundle';
import { generatedBodies } from '../fast-session';
import { loadController, loadWorld } from '../load';

/** What `layerbot bench --json` prints. */
export interface BenchReport {
  /** One value-iteration replan (75 x 75) in the fast sandbox, over the same code as plain JavaScript. */
  readonly sandboxVsNative: number;
  /** One value-iteration replan in the fast sandbox, by grid side. */
  readonly viReplanMs: Readonly<Record<'30' | '75' | '150', number>>;
  readonly viReplanVsNative150: number;
  /** The basic controller in the office world, history recording on, run over and over. */
  readonly basicTicksPerSecond: { readonly fast: number; readonly interpreter: number };
  /** Heap held by a session's history after 10,000 ticks of value iteration on a 150 x 150 grid. */
  readonly historyBytesVi150x10k: number;
  /** The worst time to seek a tick of that history (its record and every arc's value). */
  readonly seekMs: number;
}

const HISTORY_TICKS = 10_000;
/** Seconds each ticks-per-second figure runs for. */
const SECONDS = 1.5;

/** Runs the benchmark; prints a table, or the figures as JSON. Resolves to the exit code. */
export async function benchCommand(opts: { json?: boolean }, out: (s: string) => void): Promise<number> {
  const root = repositoryRoot();
  const example = (kind: 'controllers' | 'worlds', name: string) => join(root, 'examples', kind, `${name}.${kind === 'worlds' ? 'world' : 'controller'}.json`);
  const viExample = loadController(example('controllers', 'value-iteration'));
  const basicController = loadController(example('controllers', 'basic'));
  const office = loadWorld(example('worlds', 'office'));
  const vi = compileController(viExample, generateBody).find((f) => f.name === 'valueIteration');
  if (!vi) throw new Error('The value-iteration example has no function "valueIteration".');
  const viController = withCellSize(viExample, 4);
  const job: BenchJob = {
    vi,
    viController,
    viBodies: generatedBodies(viController),
    viWorld: viBenchWorld(),
    historyTicks: HISTORY_TICKS,
    basicController,
    basicBodies: generatedBodies(basicController),
    office,
    seconds: SECONDS,
  };
  const fast = await inWorker(job);

  const reference = new Session(office, basicController, { sandbox: createInterpreterSandbox, generateBody });
  ticksPerSecond(reference, 0.2);
  const interpreterTicks = ticksPerSecond(reference, SECONDS);
  reference.dispose();

  const [small, mid, large] = VI_SIZES.map((n) => fast.viReplanMs[n]);
  const report: BenchReport = {
    sandboxVsNative: round(fast.viReplanMs[RATIO_SIZE] / fast.viPlainMs[RATIO_SIZE], 2),
    viReplanMs: { '30': round(small, 2), '75': round(mid, 2), '150': round(large, 2) },
    viReplanVsNative150: round(large / fast.viPlainMs[150], 2),
    basicTicksPerSecond: { fast: Math.round(fast.basicTicksPerSecond), interpreter: Math.round(interpreterTicks) },
    historyBytesVi150x10k: fast.historyBytes,
    seekMs: round(fast.seekMs, 3),
  };
  out(opts.json ? JSON.stringify(report) : table(report, fast));
  return 0;
}

function inWorker(job: BenchJob): Promise<FastFigures> {
  const worker = new Worker(workerBundle('bench-worker'), { resourceLimits: { maxOldGenerationSizeMb: 8192 } });
  return new Promise<FastFigures>((resolve, reject) => {
    worker.once('message', (figures: FastFigures) => {
      void worker.terminate();
      resolve(figures);
    });
    worker.once('error', reject);
    worker.postMessage(job);
  }).finally(() => void worker.terminate());
}

function round(x: number, digits: number): number {
  const f = 10 ** digits;
  return Math.round(x * f) / f;
}

const number = (n: number) => n.toLocaleString('en-US');

function table(r: BenchReport, fast: FastFigures): string {
  const mb = (b: number) => `${(b / 1e6).toFixed(1)} MB`;
  const rows: [string, string, string][] = [
    [`fast sandbox vs plain JS (value iteration ${RATIO_SIZE}x${RATIO_SIZE})`, `${r.sandboxVsNative}x`, 'at most 3x'],
    ...VI_SIZES.map((n): [string, string, string] => [
      `value-iteration replan ${n}x${n} (plain JS ${fast.viPlainMs[n].toFixed(2)} ms)`,
      `${r.viReplanMs[String(n) as '30' | '75' | '150']} ms`,
      n === 150 ? 'under 100 ms' : '',
    ]),
    ['replan 150x150, fast sandbox vs plain JS', `${r.viReplanVsNative150}x`, ''],
    ['basic controller, office world, fast engine', `${number(r.basicTicksPerSecond.fast)} ticks/s`, 'at least 200,000'],
    ['basic controller, office world, JS-Interpreter', `${number(r.basicTicksPerSecond.interpreter)} ticks/s`, 'at least 5,000'],
    [`history of ${number(fast.historyTicks)} ticks of value iteration 150x150 (${fast.replans} replans)`, mb(r.historyBytesVi150x10k), 'under 50 MB'],
    ['worst seek of a tick (record and arcs)', `${r.seekMs} ms`, 'under 16 ms'],
  ];
  const w0 = Math.max(...rows.map((x) => x[0].length));
  const w1 = Math.max(...rows.map((x) => x[1].length));
  return ['Layerbot benchmark (one run)', ...rows.map(([a, b, c]) => `  ${a.padEnd(w0)}  ${b.padStart(w1)}  ${c ? `(target: ${c})` : ''}`.trimEnd())].join('\n');
}
