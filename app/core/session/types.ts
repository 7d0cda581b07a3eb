/**
 * Plain records the engine emits once per tick. The renderer, the CLI and the tests only read
 * them; they are frozen and share every value that did not change since the previous tick.
 */
import type { WorldEdit } from '../world/edits';
import type { WorldState } from '../world/world';

/** A line printed by a function during a tick. */
export interface OutputLine {
  readonly function: string;
  readonly layer: string;
  readonly text: string;
}

/** An error that stopped the run, attributed to the function, its layer and the block. */
export interface ControllerError {
  readonly tick: number;
  readonly function: string | null;
  readonly layer: string | null;
  readonly blockId: string | null;
  /** 'budget' | 'mutation' | 'type' | 'exception' | 'resources' | 'syntax' | 'graph' */
  readonly kind: string;
  /** The full message: `Error in function "arrived" (layer "Middle"): <what happened>`. */
  readonly message: string;
}

/** Everything about one tick. Tick 0 is the initial state (no functions ran). */
export interface TickRecord {
  readonly tick: number;
  /** The world at the end of this tick. */
  readonly world: WorldState;
  /** Each function's output this tick, in the controller's function order (undefined: did not run). */
  readonly outputs: readonly unknown[];
  /** Each random source's value this tick, in the controller's source order. */
  readonly random: readonly unknown[];
  readonly printed: readonly OutputLine[];
  readonly error: ControllerError | null;
  /** World edits the user made at this tick (applied to `world`). */
  readonly edits: readonly WorldEdit[];
}

/** Why a run ended, or 'running' while it may go on. */
export type SessionStatus = 'ready' | 'done' | 'crashed' | 'error';

/** What a run produced: the CLI's `--json` summary. */
export interface RunSummary {
  readonly ticks: number;
  readonly crashed: boolean;
  readonly crashTick: number | null;
  /** One entry per plan step, in plan order. */
  readonly goals: readonly { readonly name: string; readonly reachedTick: number | null }[];
  readonly error: string | null;
}

/** One arc as the arc table shows it. */
export interface ArcView {
  /** The source: a function name, `world.robotPos`, `random.coin`, or `previous.todo`. */
  readonly from: string;
  readonly to: string;
  readonly input: string;
  readonly previousTick: boolean;
  readonly value: unknown;
  /** True when the value differs from the same arc's value on the previous tick. */
  readonly changed: boolean;
}
