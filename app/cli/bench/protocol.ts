/** Messages between `layerbot bench` and its worker thread (bench-worker.ts). */
import type { GeneratedBody } from '../../core/controller/compile';
import type { ControllerSpec } from '../../core/controller/model';
import type { CompiledFunction } from '../../core/sandbox/types';
import type { WorldSpec } from '../../core/world/world';

/** Grid sides of the value-iteration replans. */
export const VI_SIZES = [30, 75, 150] as const;

/** The grid side `sandboxVsNative` is measured on. */
export const RATIO_SIZE = 75;

export interface BenchJob {
  /** `valueIteration`, compiled from the example's blocks. */
  readonly vi: CompiledFunction;
  /** The value-iteration controller set up for a 150 x 150 grid in `viWorld`, with its bodies. */
  readonly viController: ControllerSpec;
  readonly viBodies: Readonly<Record<string, GeneratedBody>>;
  readonly viWorld: WorldSpec;
  readonly historyTicks: number;
  /** The basic controller and the office world, with its bodies. */
  readonly basicController: ControllerSpec;
  readonly basicBodies: Readonly<Record<string, GeneratedBody>>;
  readonly office: WorldSpec;
  /** How long to run the basic controller for its ticks per second. */
  readonly seconds: number;
}

/** Parent -> worker. */
export type BenchRequest =
  /** Set up the fast sandbox of `valueIteration` (and keep the job for `rest`). */
  | { readonly type: 'setup'; readonly job: BenchJob }
  /** Time `runs` replans on an n x n grid, after `warmup` untimed ones. */
  | { readonly type: 'replan'; readonly n: number; readonly runs: number; readonly warmup: number }
  /** Everything else: ticks per second, history memory, seeks. */
  | { readonly type: 'rest' };

/** Worker -> parent. */
export type BenchReply =
  | { readonly type: 'ready' }
  | { readonly type: 'replan'; readonly ms: readonly number[] }
  | { readonly type: 'rest'; readonly figures: FastFigures }
  | { readonly type: 'failed'; readonly message: string };

/** What the worker measured in its locked-down realm, apart from the replans. */
export interface FastFigures {
  readonly basicTicksPerSecond: number;
  readonly historyBytes: number;
  /** Ticks the history held when measured, and how many replans they contained. */
  readonly historyTicks: number;
  readonly replans: number;
  readonly seekMs: number;
}
