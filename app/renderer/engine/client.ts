/**
 * The page's side of the engine: starts the Worker, sends commands, and keeps what the Worker
 * streams (frames of every tick and world revisions) so the timeline can seek any tick without
 * asking. Arc values are fetched per tick and cached by arc, as the Worker sends only new ones.
 */
import type { ControllerSpec } from '../../core/controller/model';
import type { RunSummary, SessionStatus } from '../../core/session/types';
import type { WorldEdit } from '../../core/world/edits';
import type { WorldSpec } from '../../core/world/world';
import { generateBody } from '../../../blocks/generate';
import { Emitter } from '../app/emitter';
import { generateBodies } from './bodies';
import type { EngineCommand, EngineEvent, FunctionInfo, Speed, TickFrame, WireArc, WorldParts } from './protocol';

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
  private readonly worker: Worker;
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

  constructor() {
    this.worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: 'layerbot-engine' });
    this.worker.onmessage = (e: MessageEvent<EngineEvent>) => this.receive(e.data);
    this.worker.onerror = (e) => this.onProblem.emit(`The engine stopped unexpectedly: ${e.message || 'unknown error'}`);
  }

  get latest(): TickFrame | undefined {
    return this.frames[this.frames.length - 1];
  }

  worldAt(frame: TickFrame): WorldParts {
    return this.worlds.get(frame.worldRev) as WorldParts;
  }

  /** Starts a new session; block code is generated here, on the page (see bodies.ts). */
  load(world: WorldSpec, controller: ControllerSpec | null): void {
    this.send({ type: 'load', world, controller, bodies: controller ? generateBodies(controller, generateBody) : {} });
  }
  step(): void {
    this.send({ type: 'step' });
  }
  run(speed: Speed, maxTicks: number): void {
    this.send({ type: 'run', speed, maxTicks });
  }
  setSpeed(speed: Speed): void {
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
    switch (ev.type) {
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
