/**
 * `layerbot bench`: the performance figures of DESIGN.md section 9, measured in one run. The fast
 * engine's figures come from a worker thread (its realm is locked down); the reference engine's and
 * the plain-JavaScript baseline's from this thread, whose realm is a normal one.
 *
 * The replans are compared fairly: the same generated code on the same inputs, each side warmed up
 * the same way, timed in alternating rounds (which side goes first alternates too), and each figure
 * is the median of every timed run. The baseline is the bare function call, with nothing checked or
 * frozen; the sandbox's figure includes what Run pays: guards, the result's check and freezing.
 */
import { join } from 'node:path';
import { Worker } from 'node:worker_threads';
import { generateBody } from '../../../blocks/generate';
import { compileController } from '../../core/controller/compile';
import { createInterpreterSandbox } from '../../core/sandbox/interpreter';
import { Session } from '../../core/session/session';
import { median, medianTicksPerSecond, ticksPerSecond, timeMs } from '../bench/measure';
import { plainFunctions } from '../bench/plain-sandbox';
import type { BenchJob, BenchReply, BenchRequest, FastFigures } from '../bench/protocol';
import { RATIO_SIZE, VI_SIZES } from '../bench/protocol';
import { viArguments, viBenchWorld, withCellSize } from '../bench/vi-setup';
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
/** Seconds each ticks-per-second figure runs for (the median of five stretches). */
const SECONDS = 2;

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
  const worker = new BenchWorker();
  let fast: FastFigures;
  const viReplanMs: Record<number, number> = {};
  const viPlainMs: Record<number, number> = {};
  try {
    await worker.ask({ type: 'setup', job });
    const plain = plainFunctions([vi])[0];
    for (const n of VI_SIZES) {
      const args = viArguments(n) as unknown[];
      const runs = n >= 150 ? 3 : 5;
      const f: number[] = [];
      const p: number[] = [];
      const plainRuns = (warmup: number): void => {
        for (let i = 0; i < warmup; i++) plain(...args);
        for (let i = 0; i < runs; i++) p.push(timeMs(() => plain(...args)));
      };
      const fastRuns = async (warmup: number): Promise<void> => {
        const reply = await worker.ask({ type: 'replan', n, runs, warmup });
        if (reply.type === 'replan') f.push(...reply.ms);
      };
      for (let r = 0; r < ROUNDS; r++) {
        const warmup = r === 0 ? 3 : 1;
        if (r % 2 === 0) {
          plainRuns(warmup);
          await fastRuns(warmup);
        } else {
          await fastRuns(warmup);
          plainRuns(warmup);
        }
      }
      viReplanMs[n] = median(f);
      viPlainMs[n] = median(p);
    }
    const reply = await worker.ask({ type: 'rest' });
    if (reply.type !== 'rest') throw new Error('unreachable');
    fast = reply.figures;
  } finally {
    worker.close();
  }

  const reference = new Session(office, basicController, { sandbox: createInterpreterSandbox, generateBody });
  ticksPerSecond(reference, 0.2);
  const interpreterTicks = medianTicksPerSecond(reference, SECONDS);
  reference.dispose();

  const [small, mid, large] = VI_SIZES.map((n) => viReplanMs[n]);
  const report: BenchReport = {
    sandboxVsNative: round(viReplanMs[RATIO_SIZE] / viPlainMs[RATIO_SIZE], 2),
    viReplanMs: { '30': round(small, 2), '75': round(mid, 2), '150': round(large, 2) },
    viReplanVsNative150: round(large / viPlainMs[150], 2),
    basicTicksPerSecond: { fast: Math.round(fast.basicTicksPerSecond), interpreter: Math.round(interpreterTicks) },
    historyBytesVi150x10k: fast.historyBytes,
    seekMs: round(fast.seekMs, 3),
  };
  out(opts.json ? JSON.stringify(report) : table(report, fast, viPlainMs));
  return 0;
}

/** Rounds of alternating replans per grid side. */
const ROUNDS = 4;

/** The locked-down worker thread the fast engine is measured in, one request at a time. */
class BenchWorker {
  private readonly worker = new Worker(workerBundle('bench-worker'), { resourceLimits: { maxOldGenerationSizeMb: 8192 } });

  ask(req: BenchRequest): Promise<BenchReply> {
    return new Promise<BenchReply>((resolve, reject) => {
      const onError = (e: Error): void => reject(e);
      this.worker.once('error', onError);
      this.worker.once('message', (reply: BenchReply) => {
        this.worker.off('error', onError);
        if (reply.type === 'failed') reject(new Error(reply.message));
        else resolve(reply);
      });
      this.worker.postMessage(req);
    });
  }

  close(): void {
    void this.worker.terminate();
  }
}

function round(x: number, digits: number): number {
  const f = 10 ** digits;
  return Math.round(x * f) / f;
}

const number = (n: number) => n.toLocaleString('en-US');

function table(r: BenchReport, fast: FastFigures, plainMs: Readonly<Record<number, number>>): string {
  const mb = (b: number) => `${(b / 1e6).toFixed(1)} MB`;
  const rows: [string, string, string][] = [
    [`fast sandbox vs plain JS (value iteration ${RATIO_SIZE}x${RATIO_SIZE})`, `${r.sandboxVsNative}x`, 'at most 3x'],
    ...VI_SIZES.map((n): [string, string, string] => [
      `value-iteration replan ${n}x${n} (plain JS ${plainMs[n].toFixed(2)} ms)`,
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
