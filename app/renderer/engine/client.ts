/**
 * The page's side of the engine: starts the Worker, sends commands, and keeps what the Worker
 * streams (frames of every tick and world revisions) so the timeline can seek any tick without
 * asking. Arc values are fetched per tick and cached by arc, as the Worker sends only new ones.
 *
 * The watchdog: the page pings the Worker every second; the Worker answers between slices of
 * ticks. A Worker that has not answered for WATCHDOG_MS (by engine) is stuck in one call that no step budget
 * can stop (a regular expression that backtracks for ever, a huge text) or has died (out of
 * memory). The page then ends it and starts a new one, which rebuilds the session up to the last
 * tick the page has and computes the next tick again, reporting each call it starts. If it gets
 * stuck again, the page knows the function: a third Worker rebuilds the session and records the
 * error at that tick, naming the function and its layer. Every tick is pure, so the rebuild gives
 * the same ticks again.
 */
import type { ControllerSpec } from '../../core/controller/model';
import { functionErrorMessage } from '../../core/sandbox/types';
import type { RunSummary, SessionStatus } from '../../core/session/types';
import type { WorldEdit } from '../../core/world/edits';
import type { WorldSpec } from '../../core/world/world';
import { generateBody } from '../../../blocks/generate';
import { Emitter } from '../app/emitter';
import { generateBodies } from './bodies';
import type { BodyTable } from './bodies';
import type { EngineCommand, EngineEvent, EngineName, FunctionInfo, Speed, StoppedCall, TickFrame, TimedEdit, WireArc, WorldParts } from './protocol';

/**
 * How long the Worker may leave a ping unanswered before the page ends it. The fast engine's step
 * budget ends any loop in well under a second, so only a slow built-in takes longer; JS-Interpreter
 * is some thousand times slower, and a legitimate tick of a big controller can take many seconds.
 */
export const WATCHDOG_MS: Readonly<Record<EngineName, number>> = { fast: 5000, interpreter: 60_000 };
const PING_MS = 1000;

/** What the Worker was last given to run: enough to rebuild the session in a new Worker. */
interface Loaded {
  world: WorldSpec;
  readonly controller: ControllerSpec;
  readonly bodies: BodyTable;
  readonly seed?: number;
}

/** One arc at one tick, with its value filled in from the cache. */
export type ArcRow = Omit<WireArc, 'cached'>;

export interface EngineSnapshot {
  readonly running: boolean;
  readonly status: SessionStatus;
  readonly hasController: boolean;
  readonly summary: RunSummary | null;
  readonly note: string | null;
  readonly ticksPerSecond: number;
}

export class EngineClient {
  private worker: Worker;
  /** The engine the Worker runs ticks with (known once it has started), and why not the fast one. */
  engine: EngineName | null = null;
  engineNote: string | null = null;
  private loaded: Loaded | null = null;
  /** The oldest ping not answered yet (time sent), or null. */
  private unanswered: number | null = null;
  private pingId = 0;
  /** While a restoring Worker computes the tick that got stuck: the function it last started. */
  private probe: { tick: number; index: number | null } | null = null;
  private readonly workerName: string;
  /** The last run asked for (a restore goes on with it). */
  private lastRun: { speed: Speed; maxTicks: number } = { speed: 0, maxTicks: 1 };
  /** frames[t] is tick t. */
  readonly frames: TickFrame[] = [];
  readonly worlds = new Map<number, WorldParts>();
  functions: readonly FunctionInfo[] = [];
  state: EngineSnapshot = { running: false, status: 'ready', hasController: false, summary: null, note: null, ticksPerSecond: 0 };
  private generation = -1;
  private arcCache: unknown[] = [];
  private nextId = 1;
  private readonly waiting = new Map<number, (arcs: ArcRow[]) => void>();

  /** A new session began (load or reset): everything recorded before is gone. */
  readonly onLoaded = new Emitter<void>();
  /** New ticks arrived (or the latest was replaced). */
  readonly onTicks = new Emitter<void>();
  readonly onStatus = new Emitter<EngineSnapshot>();
  readonly onProblem = new Emitter<string>();

  /** `engine`: the one to ask the Worker for; by default the fast one, unless the page's URL has `?engine=interpreter`. */
  constructor(engine: EngineName = new URLSearchParams(location.search).get('engine') === 'interpreter' ? 'interpreter' : 'fast') {
    this.workerName = engine === 'interpreter' ? 'layerbot-engine-interpreter' : 'layerbot-engine';
    this.worker = this.startWorker();
    setInterval(() => this.watch(), PING_MS);
  }

  private startWorker(): Worker {
    const worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: this.workerName });
    worker.onmessage = (e: MessageEvent<EngineEvent>) => {
      if (worker === this.worker) this.receive(e.data);
    };
    worker.onerror = (e) => {
      if (worker !== this.worker) return;
      e.preventDefault();
      // A Worker that failed while running student code is treated as stuck; otherwise say so.
      if (this.loaded) this.stuck();
      else this.onProblem.emit(`The engine stopped unexpectedly: ${e.message || 'unknown error'}`);
    };
    this.unanswered = null;
    return worker;
  }

  private limitMs(): number {
    return WATCHDOG_MS[this.engine ?? (this.workerName.endsWith('-interpreter') ? 'interpreter' : 'fast')];
  }

  /** Pings the Worker, and ends it when it has not answered for too long. */
  private watch(): void {
    if (this.unanswered !== null && performance.now() - this.unanswered > this.limitMs()) return this.stuck();
    this.unanswered ??= performance.now();
    this.send({ type: 'ping', id: ++this.pingId });
  }

  /** The Worker is stuck or dead: replace it and rebuild the session (see the file's comment). */
  private stuck(): void {
    this.worker.terminate();
    this.worker = this.startWorker();
    for (const done of this.waiting.values()) done([]);
    this.waiting.clear();
    this.arcCache = [];
    const loaded = this.loaded;
    if (!loaded) return;
    const known = this.frames.length - 1;
    let upTo = known;
    let stopped: StoppedCall | null = null;
    if (this.probe) {
      // The probing Worker got as far as the tick before the one it got stuck in.
      upTo = Math.max(known, this.probe.tick - 1);
      const placed = this.probe.index !== null ? this.functions[this.probe.index] : undefined;
      const seconds = this.limitMs() / 1000;
      const what =
        `it ran for more than ${seconds} seconds in one tick and was stopped. ` +
        'The step budget cannot stop a slow built-in operation: look for a regular expression that backtracks a lot, or a huge text or list.';
      stopped = {
        function: placed?.name ?? null,
        layer: placed?.layer ?? null,
        kind: 'resources',
        message: placed ? functionErrorMessage(placed.name, placed.layer, what) : `Error: ${what}`,
      };
      this.probe = null;
    } else this.probe = { tick: known + 1, index: null };
    const resume = this.state.running ? this.lastRun : null;
    const edits: TimedEdit[] = [];
    for (const f of this.frames) for (const edit of f.edits) edits.push({ tick: f.tick, edit });
    if (stopped) {
      this.state = { ...this.state, running: false };
      this.onStatus.emit(this.state);
    }
    this.send({
      type: 'restore',
      generation: this.generation,
      world: loaded.world,
      controller: loaded.controller,
      bodies: loaded.bodies,
      ...(loaded.seed !== undefined ? { seed: loaded.seed } : {}),
      upTo,
      known,
      edits,
      stopped,
      resume: stopped ? null : resume,
    });
  }

  get latest(): TickFrame | undefined {
    return this.frames[this.frames.length - 1];
  }

  worldAt(frame: TickFrame): WorldParts {
    return this.worlds.get(frame.worldRev) as WorldParts;
  }

  /** Starts a new session; block code is generated here, on the page (see bodies.ts). */
  load(world: WorldSpec, controller: ControllerSpec | null): void {
    const bodies = controller ? generateBodies(controller, generateBody) : {};
    this.loaded = controller ? { world, controller, bodies } : null;
    this.probe = null;
    this.send({ type: 'load', world, controller, bodies });
  }
  step(): void {
    this.send({ type: 'step' });
  }
  run(speed: Speed, maxTicks: number): void {
    this.lastRun = { speed, maxTicks };
    this.send({ type: 'run', speed, maxTicks });
  }
  setSpeed(speed: Speed): void {
    this.lastRun = { ...this.lastRun, speed };
    this.send({ type: 'speed', speed });
  }
  /** Stops at once on the page (no more frames are drawn as current) and tells the Worker. */
  stop(): void {
    this.send({ type: 'stop' });
    if (this.state.running) {
      this.state = { ...this.state, running: false };
      this.onStatus.emit(this.state);
    }
  }
  reset(world?: WorldSpec): void {
    if (world && this.loaded) this.loaded.world = world;
    this.probe = null;
    this.send(world ? { type: 'reset', world } : { type: 'reset' });
  }
  editWorld(edit: WorldEdit): void {
    this.send({ type: 'editWorld', edit });
  }

  /** Every arc's value at a tick. */
  arcs(tick: number): Promise<ArcRow[]> {
    const id = this.nextId++;
    return new Promise((resolve) => {
      this.waiting.set(id, resolve);
      this.send({ type: 'arcs', id, tick });
    });
  }

  private send(cmd: EngineCommand): void {
    this.worker.postMessage(cmd);
  }

  private receive(ev: EngineEvent): void {
    // Any message shows the Worker is alive (a restore computing for long sends `restored` often).
    this.unanswered = null;
    switch (ev.type) {
      case 'engine':
        this.engine = ev.engine;
        this.engineNote = ev.note;
        this.onStatus.emit(this.state);
        return;
      case 'pong':
      case 'restored':
        return;
      case 'calling':
        if (this.probe && ev.generation === this.generation) this.probe = { tick: ev.tick, index: ev.index };
        return;
      case 'loaded':
        this.generation = ev.generation;
        this.frames.length = 0;
        this.worlds.clear();
        this.arcCache = [];
        this.worlds.set(ev.world.rev, ev.world);
        this.frames.push(ev.frame);
        this.functions = ev.functions;
        this.state = { ...this.state, status: ev.status, hasController: ev.hasController, running: false, note: null };
        this.onLoaded.emit();
        return;
      case 'ticks':
        if (ev.generation !== this.generation) return;
        for (const w of ev.worlds) this.worlds.set(w.rev, w);
        for (const f of ev.frames) {
          if (f.tick < this.frames.length) this.frames[f.tick] = f;
          else this.frames.push(f);
        }
        this.onTicks.emit();
        return;
      case 'status':
        if (ev.generation !== this.generation) return;
        // The tick that got stuck went through this time (or the run ended): no probe pending.
        if (!ev.running) this.probe = null;
        this.state = {
          running: ev.running,
          status: ev.status,
          hasController: this.state.hasController,
          summary: ev.summary,
          note: ev.note,
          ticksPerSecond: ev.ticksPerSecond,
        };
        this.onStatus.emit(this.state);
        return;
      case 'problem':
        this.onProblem.emit(ev.message);
        return;
      case 'arcs': {
        const rows: ArcRow[] = ev.arcs.map((a, i) => {
          if (!a.cached) this.arcCache[i] = a.value;
          return { from: a.from, to: a.to, input: a.input, previousTick: a.previousTick, changed: a.changed, value: this.arcCache[i] };
        });
        const done = this.waiting.get(ev.id);
        this.waiting.delete(ev.id);
        done?.(rows);
        return;
      }
    }
  }
}
