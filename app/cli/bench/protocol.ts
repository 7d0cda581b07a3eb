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

/** What the worker measured, all in one realm (locked down). */
export interface FastFigures {
  /** Median milliseconds of one replan, by grid side, in the fast sandbox and as plain JavaScript. */
  readonly viReplanMs: Readonly<Record<string, number>>;
  readonly viPlainMs: Readonly<Record<string, number>>;
  readonly basicTicksPerSecond: number;
  readonly historyBytes: number;
  /** Ticks the history held when measured, and how many replans they contained. */
  readonly historyTicks: number;
  readonly replans: number;
  readonly seekMs: number;
}
