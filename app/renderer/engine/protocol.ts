/**
 * The one typed message union between the page and the engine Worker.
 *
 * The Worker holds the Session (the history of every tick). It streams each tick to the page as a
 * small `TickFrame` (pose, whisker, crash, plan progress, printed lines, error, edits) and sends the
 * world's walls, goals and plan only when they change (a `WorldParts` revision), so a run in a
 * world of 1,000 walls does not copy the walls every tick. Arc values, which can be large grids,
 * are fetched per tick on demand (`arcs`), and a value the page already has is not sent again.
 * Seeking is done by the page over its frames; the Worker is only asked for that tick's arcs.
 */
import type { ControllerSpec } from '../../core/controller/model';
import type { ControllerError, OutputLine, RunSummary, SessionStatus } from '../../core/session/types';
import type { WorldEdit } from '../../core/world/edits';
import type { Body, Bounds, Crash, Goal, WorldSpec } from '../../core/world/world';
import type { Segment } from '../../core/world/geometry';
import type { BodyTable } from './bodies';

/** The parts of the world that only change by edits, under a revision number. */
export interface WorldParts {
  readonly rev: number;
  readonly walls: readonly Segment[];
  readonly goals: readonly Goal[];
  readonly plan: readonly string[];
  readonly body: Body;
  readonly goalRadius: number;
  readonly bounds: Bounds | null;
}

/** What the page keeps of one tick. */
export interface TickFrame {
  readonly tick: number;
  readonly x: number;
  readonly y: number;
  readonly heading: number;
  readonly whisker: boolean;
  readonly crash: Crash | null;
  /** For each plan step, the tick it was reached, or null. */
  readonly reached: readonly (number | null)[];
  readonly printed: readonly OutputLine[];
  readonly error: ControllerError | null;
  readonly edits: readonly WorldEdit[];
  /** The `WorldParts` revision in force at the end of this tick. */
  readonly worldRev: number;
}

/** A function of the loaded controller, for the panels (arc table, errors, editor). */
export interface FunctionInfo {
  readonly name: string;
  readonly layer: string;
  readonly output: string;
}

/** One arc at one tick. `cached`: the value is the one the page received last for this arc. */
export interface WireArc {
  readonly from: string;
  readonly to: string;
  readonly input: string;
  readonly previousTick: boolean;
  readonly changed: boolean;
  readonly value: unknown;
  readonly cached: boolean;
}

/** Ticks per second; 0 means as fast as the engine can go. */
export type Speed = number;

/** The sandbox engine the Worker runs ticks with: SES compartments, or JS-Interpreter. */
export type EngineName = 'fast' | 'interpreter';

/** A world edit and the tick it was recorded at (a restore replays them). */
export interface TimedEdit {
  readonly tick: number;
  readonly edit: WorldEdit;
}

/** An error the page's watchdog found: a call it had to stop by ending the Worker. */
export interface StoppedCall {
  readonly function: string | null;
  readonly layer: string | null;
  readonly kind: string;
  readonly message: string;
}

export type EngineCommand =
  /** Starts a new session (tick 0), with the page-generated block code. A null controller shows the world alone. */
  | { readonly type: 'load'; readonly world: WorldSpec; readonly controller: ControllerSpec | null; readonly bodies: BodyTable; readonly seed?: number }
  | { readonly type: 'step' }
  /** Runs until the run ends, `maxTicks` more ticks pass, or `stop`. */
  | { readonly type: 'run'; readonly speed: Speed; readonly maxTicks: number }
  | { readonly type: 'speed'; readonly speed: Speed }
  | { readonly type: 'stop' }
  /** Back to tick 0, with a new world when given. */
  | { readonly type: 'reset'; readonly world?: WorldSpec }
  /** A drag while the robot runs: recorded at the current tick. */
  | { readonly type: 'editWorld'; readonly edit: WorldEdit }
  | { readonly type: 'arcs'; readonly id: number; readonly tick: number }
  /** Answered with `pong` between slices: the page's watchdog hears that the Worker is not stuck. */
  | { readonly type: 'ping'; readonly id: number }
  /**
   * A new Worker (the watchdog ended the last one) rebuilds the session the page shows: it loads,
   * computes ticks 1..upTo again with the edits at their ticks (sending none of them), then either
   * records `stopped` at tick upTo + 1, or goes on (the run, or one step) while reporting every
   * call it starts (`calling`), so that a second stop can name the function.
   */
  | {
      readonly type: 'restore';
      readonly generation: number;
      readonly world: WorldSpec;
      readonly controller: ControllerSpec;
      readonly bodies: BodyTable;
      readonly seed?: number;
      readonly upTo: number;
      /** The page's latest tick: ticks after it are sent as they are computed. */
      readonly known: number;
      readonly edits: readonly TimedEdit[];
      readonly stopped: StoppedCall | null;
      /** The run to go on with (when the stuck Worker was running), or null (it was stepping). */
      readonly resume: { readonly speed: Speed; readonly maxTicks: number } | null;
    };

export type EngineEvent =
  /** A new session at tick 0 (after load or reset): the page drops what it had. */
  | {
      readonly type: 'loaded';
      readonly generation: number;
      readonly world: WorldParts;
      readonly frame: TickFrame;
      readonly functions: readonly FunctionInfo[];
      readonly hasController: boolean;
      readonly status: SessionStatus;
    }
  /** New ticks (and the world revisions they introduced), in order. */
  | {
      readonly type: 'ticks';
      readonly generation: number;
      readonly worlds: readonly WorldParts[];
      readonly frames: readonly TickFrame[];
      /** The latest tick's record was replaced (an edit at the current tick). */
      readonly replacedLatest: boolean;
    }
  | {
      readonly type: 'status';
      readonly generation: number;
      readonly running: boolean;
      readonly status: SessionStatus;
      readonly summary: RunSummary | null;
      /** Why a run stopped, in words, when it was not the user. */
      readonly note: string | null;
      /** Ticks computed per second during the last run slice (0 when idle). */
      readonly ticksPerSecond: number;
    }
  /** The controller or world could not be loaded; the message says why and where. */
  | { readonly type: 'problem'; readonly message: string }
  | { readonly type: 'arcs'; readonly id: number; readonly tick: number; readonly arcs: readonly WireArc[] }
  /** Sent once when the Worker starts: the engine it runs ticks with, and why not the fast one. */
  | { readonly type: 'engine'; readonly engine: EngineName; readonly note: string | null }
  | { readonly type: 'pong'; readonly id: number }
  /** During a restore's probing tick: function number `index` (session order) starts. */
  | { readonly type: 'calling'; readonly generation: number; readonly tick: number; readonly index: number }
  /** A restore rebuilt ticks 0..tick (still alive while it works: sent every ~100 ms as well). */
  | { readonly type: 'restored'; readonly generation: number; readonly tick: number };
