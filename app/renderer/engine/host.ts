/**
 * The engine side of the Worker: holds the Session, answers commands, paces runs and streams
 * batches of frames. Kept apart from `worker.ts` (which only binds it to the Worker's messages) so
 * it has one job and could run on the page too.
 */
import type { ControllerSpec } from '../../core/controller/model';
import type { SandboxFactory } from '../../core/sandbox/types';
import { Session } from '../../core/session/session';
import type { SessionStatus, TickRecord } from '../../core/session/types';
import type { WorldEdit } from '../../core/world/edits';
import { editState } from '../../core/world/edits';
import type { WorldSpec, WorldState } from '../../core/world/world';
import { initialState } from '../../core/world/world';
import type { BodyTable } from './bodies';
import { tableGenerator } from './bodies';
import { frameOf, WorldRevisions } from './frames';
import type { EngineCommand, EngineEvent, FunctionInfo, Speed, TickFrame, WireArc, WorldParts } from './protocol';

type RestoreCommand = Extract<EngineCommand, { type: 'restore' }>;

/** Longest stretch of computing before the Worker looks at its messages again (Stop acts at once). */
const SLICE_MS = 12;
/**
 * Ticks computed while probing after a restore (see `restore`): more than one slice of the
 * fastest engine computes, so the tick that got stuck is among them.
 */
const PROBE_TICKS = 20_000;

type Post = (event: EngineEvent) => void;
type Clock = () => number;
type Yield = (fn: () => void, ms: number) => void;

export class EngineHost {
  private session: Session | null = null;
  /** The world alone, when no controller is loaded (Create mode, or a controller that failed). */
  private bare: WorldState | null = null;
  private generation = 0;
  private revisions = new WorldRevisions();
  private pending: { frames: TickFrame[]; worlds: WorldParts[]; replaced: boolean } = { frames: [], worlds: [], replaced: false };
  private running = false;
  private speed: Speed = 0;
  private runStart = 0;
  private runStartTick = 0;
  private runUntil = 0;
  private scheduled = false;
  private ticksPerSecond = 0;
  /** The last value sent for each arc (by index), so unchanged values are not copied again. */
  private sentArcValues: unknown[] = [];
  /** Until this tick, every call starting is reported to the page (`calling`): see `restore`. */
  private probeUntil = 0;
  private readonly sandbox: SandboxFactory;

  constructor(
    sandbox: SandboxFactory,
    private readonly post: Post,
    private readonly now: Clock,
    private readonly later: Yield,
  ) {
    this.sandbox = (functions) => {
      const inner = sandbox(functions);
      return {
        call: (index, args, budget) => {
          const tick = this.session ? this.session.tick + 1 : 0;
          if (tick <= this.probeUntil) this.post({ type: 'calling', generation: this.generation, tick, index });
          return inner.call(index, args, budget);
        },
        dispose: () => inner.dispose(),
      };
    };
  }

  handle(cmd: EngineCommand): void {
    switch (cmd.type) {
      case 'load':
        return this.load(cmd.world, cmd.controller, cmd.bodies, cmd.seed);
      case 'step':
        if (this.running) this.stop(null);
        return this.stepOnce();
      case 'run':
        return this.run(cmd.speed, cmd.maxTicks);
      case 'speed':
        this.speed = cmd.speed;
        this.runStart = this.now();
        this.runStartTick = this.session?.tick ?? 0;
        return;
      case 'stop':
        return this.stop(null);
      case 'reset':
        return this.reset(cmd.world);
      case 'editWorld':
        return this.edit(cmd.edit);
      case 'arcs':
        return this.arcs(cmd.id, cmd.tick);
      case 'ping':
        return this.post({ type: 'pong', id: cmd.id });
      case 'restore':
        return this.restore(cmd);
    }
  }

  /**
   * Rebuilds the page's session in this (new) Worker after the watchdog ended the last one; see
   * the `restore` command. World revisions are numbered as the first Worker numbered them, since
   * the same records are met in the same order.
   */
  private restore(cmd: RestoreCommand): void {
    this.stop(null, false);
    this.session?.dispose();
    this.session = null;
    this.bare = null;
    try {
      this.session = new Session(cmd.world, cmd.controller, { sandbox: this.sandbox, generateBody: tableGenerator(cmd.bodies), ...(cmd.seed !== undefined ? { seed: cmd.seed } : {}) });
    } catch (e) {
      this.post({ type: 'problem', message: e instanceof Error ? e.message : String(e) });
      this.bare = initialState(cmd.world);
      this.announce();
      return;
    }
    const s = this.session;
    this.generation = cmd.generation;
    this.revisions = new WorldRevisions();
    this.pending = { frames: [], worlds: [], replaced: false };
    this.sentArcValues = [];
    const edits = new Map<number, WorldEdit[]>();
    for (const { tick, edit } of cmd.edits) edits.set(tick, [...(edits.get(tick) ?? []), edit]);
    const replayEdits = (tick: number): void => {
      for (const edit of edits.get(tick) ?? []) {
        s.editWorld(edit);
        if (tick > cmd.known) this.queue(s.history.latest, true);
        else this.revisions.revisionOf(s.history.latest.world);
      }
    };
    this.revisions.revisionOf(s.history.latest.world);
    replayEdits(0);
    let alive = this.now();
    while (s.tick < cmd.upTo && s.status === 'ready') {
      const record = s.step();
      // Ticks the page has are only counted again; later ones (computed by the stuck Worker but
      // never sent) go to the page as usual.
      if (record.tick > cmd.known) this.queue(record);
      else this.revisions.revisionOf(record.world);
      replayEdits(s.tick);
      if (this.now() - alive > 100) {
        alive = this.now();
        this.post({ type: 'restored', generation: this.generation, tick: s.tick });
      }
    }
    this.post({ type: 'restored', generation: this.generation, tick: s.tick });
    this.probeUntil = 0;
    if (s.status === 'ready' && cmd.stopped) this.queue(s.stopNextTick({ ...cmd.stopped, blockId: null }));
    else if (s.status === 'ready') {
      // Go on as the stuck Worker did, reporting every call: if it gets stuck again, the page
      // knows the function. A tick that goes through this time is kept, as any other.
      this.probeUntil = s.tick + PROBE_TICKS;
      if (cmd.resume) return this.run(cmd.resume.speed, cmd.resume.maxTicks);
      return this.stepOnce();
    }
    this.flush();
    this.postStatus(null);
  }

  private load(world: WorldSpec, controller: ControllerSpec | null, bodies: BodyTable, seed: number | undefined): void {
    this.stop(null, false);
    this.session?.dispose();
    this.session = null;
    this.bare = null;
    if (controller) {
      try {
        this.session = new Session(world, controller, { sandbox: this.sandbox, generateBody: tableGenerator(bodies), ...(seed !== undefined ? { seed } : {}) });
      } catch (e) {
        this.post({ type: 'problem', message: e instanceof Error ? e.message : String(e) });
      }
    }
    if (!this.session) this.bare = initialState(world);
    this.announce();
  }

  private reset(world?: WorldSpec): void {
    this.stop(null, false);
    if (this.session) this.session.reset(world);
    else if (world) this.bare = initialState(world);
    else if (this.bare) this.bare = initialState(this.bareSpec());
    this.announce();
  }

  /** Rebuilds a spec from the bare world so Reset restores the world as edited (no controller). */
  private bareSpec(): WorldSpec {
    const b = this.bare as WorldState;
    return { name: 'world', walls: b.walls, goals: b.goals, plan: b.plan, robot: b.robot, body: b.body, goalRadius: b.goalRadius, ...(b.bounds ? { bounds: b.bounds } : {}) };
  }

  private announce(): void {
    this.generation += 1;
    this.revisions = new WorldRevisions();
    this.pending = { frames: [], worlds: [], replaced: false };
    this.sentArcValues = [];
    const record = this.session ? this.session.history.latest : this.bareRecord();
    const { rev, parts } = this.revisions.revisionOf(record.world);
    const functions: FunctionInfo[] = this.session
      ? this.session.functions.map(({ fn, layer }) => ({ name: fn.name, layer: layer.name, output: fn.output }))
      : [];
    this.post({
      type: 'loaded',
      generation: this.generation,
      world: parts as WorldParts,
      frame: frameOf(record, rev),
      functions,
      hasController: this.session !== null,
      status: this.status(),
    });
    this.postStatus(null);
  }

  private bareRecord(): TickRecord {
    return { tick: 0, world: this.bare as WorldState, outputs: [], random: [], printed: [], error: null, edits: [] };
  }

  private status(): SessionStatus {
    return this.session ? this.session.status : 'ready';
  }

  private stepOnce(): void {
    if (!this.session || this.session.status !== 'ready') return this.postStatus(this.session ? null : 'Load a controller to run the robot.');
    this.queue(this.session.step());
    this.flush();
    this.postStatus(null);
  }

  private run(speed: Speed, maxTicks: number): void {
    if (!this.session) return this.postStatus('Load a controller to run the robot.');
    if (this.session.status !== 'ready') return this.postStatus(null);
    this.speed = speed;
    this.running = true;
    this.runStart = this.now();
    this.runStartTick = this.session.tick;
    this.runUntil = this.session.tick + Math.max(1, maxTicks);
    this.postStatus(null);
    this.schedule(0);
  }

  private stop(note: string | null, announce = true): void {
    const was = this.running;
    this.running = false;
    this.ticksPerSecond = 0;
    this.flush();
    if (announce && (was || note)) this.postStatus(note);
  }

  private schedule(ms: number): void {
    if (this.scheduled) return;
    this.scheduled = true;
    this.later(() => {
      this.scheduled = false;
      this.slice();
    }, ms);
  }

  /** Computes ticks for up to SLICE_MS, then yields so a Stop can arrive. */
  private slice(): void {
    const s = this.session;
    if (!this.running || !s) return;
    const start = this.now();
    const startTick = s.tick;
    // At a set speed, the ticks due by now; at full speed, as many as fit in the slice.
    const due = this.speed > 0 ? this.runStartTick + Math.floor(((start - this.runStart) * this.speed) / 1000) + 1 : Infinity;
    while (s.status === 'ready' && s.tick < this.runUntil && s.tick < due) {
      this.queue(s.step());
      if (this.now() - start >= SLICE_MS) break;
    }
    const elapsed = this.now() - start;
    if (s.tick > startTick && elapsed > 0) this.ticksPerSecond = ((s.tick - startTick) * 1000) / elapsed;
    if (s.status !== 'ready' || s.tick >= this.runUntil) {
      const note = s.status === 'ready' ? `Paused after ${s.tick - this.runStartTick} ticks; press Run to go on.` : null;
      this.running = false;
      this.flush();
      this.postStatus(note);
      return;
    }
    // Every slice's ticks go to the page at once (a slice is ~12 ms, under a frame): when a call
    // gets stuck, the page holds every tick before the slice it happened in (see client.ts).
    this.flush();
    const wait = this.speed > 0 ? Math.max(0, this.runStart + ((s.tick + 1 - this.runStartTick) * 1000) / this.speed - this.now()) : 0;
    this.schedule(wait);
  }

  private edit(edit: WorldEdit): void {
    try {
      if (this.session) {
        this.session.editWorld(edit);
        this.queue(this.session.history.latest, true);
      } else if (this.bare) {
        this.bare = editState(this.bare, edit);
        this.queue(this.bareRecord(), true);
      }
      this.flush();
      this.postStatus(null);
    } catch (e) {
      this.post({ type: 'problem', message: e instanceof Error ? e.message : String(e) });
    }
  }

  private queue(record: TickRecord, replaced = false): void {
    const { rev, parts } = this.revisions.revisionOf(record.world);
    if (parts) this.pending.worlds.push(parts);
    const frame = frameOf(record, rev);
    const frames = this.pending.frames;
    if (replaced) {
      // The edited record replaces the latest: if that one is still queued, replace it there.
      if (frames.length && frames[frames.length - 1].tick === record.tick) frames[frames.length - 1] = frame;
      else {
        frames.push(frame);
        this.pending.replaced = true;
      }
    } else frames.push(frame);
  }

  private flush(): void {
    const p = this.pending;
    if (!p.frames.length && !p.worlds.length) return;
    this.pending = { frames: [], worlds: [], replaced: false };
    this.post({ type: 'ticks', generation: this.generation, worlds: p.worlds, frames: p.frames, replacedLatest: p.replaced });
  }

  private postStatus(note: string | null): void {
    this.post({
      type: 'status',
      generation: this.generation,
      running: this.running,
      status: this.status(),
      summary: this.session ? this.session.summary() : null,
      note,
      ticksPerSecond: this.ticksPerSecond,
    });
  }

  private arcs(id: number, tick: number): void {
    const s = this.session;
    if (!s || tick < 0 || tick >= s.history.length) return this.post({ type: 'arcs', id, tick, arcs: [] });
    const arcs: WireArc[] = s.arcs(tick).map((a, i) => {
      const cached = i in this.sentArcValues && this.sentArcValues[i] === a.value;
      this.sentArcValues[i] = a.value;
      return { from: a.from, to: a.to, input: a.input, previousTick: a.previousTick, changed: a.changed, value: cached ? null : a.value, cached };
    });
    this.post({ type: 'arcs', id, tick, arcs });
  }
}
