/**
 * A Session is a world, a controller and a sandbox: it computes ticks, records them in the
 * history and applies the user's world edits at their tick. The app (in a Worker), the CLI and the
 * tests all drive this same class, so every front end gets the same results, tick for tick.
 *
 * Tick k (k >= 1), as in SPEC.md:
 *  1. world inputs are read from the world after tick k-1;
 *  2. every function runs once in dependency order; previous-tick arcs carry tick k-1's outputs
 *     (their initial values on tick 1);
 *  3. the body command is applied: heading, clamped move, crash check, plan tracking;
 *  4. tick k is recorded. An error stops the run at that tick.
 */
import type { BodyGenerator } from '../controller/compile';
import { compileController } from '../controller/compile';
import { orderFunctions } from '../controller/graph';
import type { ControllerSpec, PlacedFunction, WorldInputName } from '../controller/model';
import { allFunctions, allRandomSources, DEFAULT_STEP_BUDGET } from '../controller/model';
import { validateController } from '../controller/validate';
import { History } from '../history/history';
import type { CompiledFunction, Sandbox, SandboxFactory, SandboxFailure } from '../sandbox/types';
import { functionErrorMessage } from '../sandbox/types';
import type { BodyCommand } from '../values';
import { deepFreeze, describeValue, formatValue, matchesType, sameValue, VALUE_TYPE_LABELS } from '../values';
import type { WorldEdit } from '../world/edits';
import { editState } from '../world/edits';
import type { Point } from '../world/geometry';
import type { WorldSpec, WorldState } from '../world/world';
import { applyCommand, initialState, planComplete } from '../world/world';
import type { RandomStream } from './random';
import { CellInterner } from './intern';
import { createStreams } from './random';
import type { ArcView, ControllerError, OutputLine, RunSummary, SessionStatus, TickRecord } from './types';

export interface SessionOptions {
  /** Creates the sandbox that runs the controller's functions. */
  readonly sandbox: SandboxFactory;
  /** Generates the bodies of blocks functions (blocks/generate.ts); null when all are text. */
  readonly generateBody: BodyGenerator | null;
  /** Overrides every random source's seed (source i gets seed + i). */
  readonly seed?: number;
}

/** Raised when a controller cannot run: every problem, each with its place in the file. */
export class ControllerInvalidError extends Error {
  constructor(readonly problems: readonly { path: string; message: string }[]) {
    super(problems.map((p) => `${p.path}: ${p.message}`).join('\n'));
    this.name = 'ControllerInvalidError';
  }
}

/**
 * Where an argument comes from, as data: the tick loop gathers arguments with one switch, which V8
 * compiles to straight-line code, where calling a different closure per arc would not inline.
 */
const enum From {
  Function,
  Previous,
  World,
  Random,
}

interface ArgPlan {
  readonly from: From;
  /** The function's or random source's index. */
  readonly index: number;
  /** The world input's name. */
  readonly input: WorldInputName;
  /** The previous-tick arc's initial value. */
  readonly initial: unknown;
}

interface TickContext {
  readonly world: Readonly<Record<WorldInputName, unknown>>;
  readonly previous: readonly unknown[] | null;
  readonly outputs: unknown[];
  readonly random: readonly unknown[];
}

const EMPTY: readonly never[] = Object.freeze([]);

export class Session {
  readonly controller: ControllerSpec;
  readonly functions: readonly PlacedFunction[];
  readonly compiled: readonly CompiledFunction[];
  private readonly order: readonly number[];
  private readonly plans: readonly (readonly ArgPlan[])[];
  /** One `undefined` per function, appended (a packed list: see `runFunction`), copied every tick. */
  private readonly noOutputs: unknown[] = [];
  /** Each function's last successful call: its arguments, its (shared) value and printed lines. */
  private lastCalls: (LastCall | null)[] = [];
  private readonly cells = new CellInterner();
  private readonly bodyIndex: number;
  private readonly budget: number;
  private readonly options: SessionOptions;
  private sandbox: Sandbox;
  private debugSandbox: Sandbox | null = null;
  private streams: RandomStream[];
  private worldSpec: WorldSpec;
  private inputsCache: { world: WorldState; tick: number; inputs: Readonly<Record<WorldInputName, unknown>> } | null = null;
  private robotPosCache: { robot: WorldState['robot']; pos: Point } | null = null;
  private currentStatus: SessionStatus = 'ready';
  history: History;

  constructor(world: WorldSpec, controller: ControllerSpec, options: SessionOptions) {
    const problems = validateController(controller);
    if (problems.length > 0) throw new ControllerInvalidError(problems);
    this.controller = deepFreeze(controller);
    this.options = options;
    this.functions = allFunctions(controller);
    const ordering = orderFunctions(controller);
    if (!ordering.ok) throw new Error('unreachable: validated controllers have no cycles');
    this.order = ordering.order;
    this.budget = controller.stepBudget ?? DEFAULT_STEP_BUDGET;
    this.compiled = compileController(controller, options.generateBody);
    this.sandbox = options.sandbox(this.compiled);
    this.bodyIndex = this.functions.findIndex((f) => f.fn.name === controller.bodyCommand);
    for (let i = 0; i < this.functions.length; i++) this.noOutputs.push(undefined);
    this.lastCalls = this.noOutputs.map(() => null);
    this.plans = this.functions.map(({ fn }) => fn.inputs.map((inp) => this.argPlan(inp.from)));
    this.worldSpec = deepFreeze(world);
    this.streams = this.newStreams();
    this.history = new History(this.firstRecord());
    this.updateStatus(this.history.latest);
  }

  /** Why the run ended, or 'ready' while it can go on. */
  get status(): SessionStatus {
    return this.currentStatus;
  }

  /** The newest tick computed. */
  get tick(): number {
    return this.history.latest.tick;
  }

  /** The world the session started from (after reset, the new one). */
  get world(): WorldSpec {
    return this.worldSpec;
  }

  /** Starts again at tick 0, with the same or a new world; random sources start over. */
  reset(world: WorldSpec = this.worldSpec): void {
    this.worldSpec = deepFreeze(world);
    this.streams = this.newStreams();
    this.inputsCache = null;
    this.lastCalls = this.noOutputs.map(() => null);
    this.cells.clear();
    this.history = new History(this.firstRecord());
    this.currentStatus = 'ready';
    this.updateStatus(this.history.latest);
  }

  /** Computes the next tick. Does nothing (and returns the newest record) once the run has ended. */
  step(): TickRecord {
    if (this.currentStatus !== 'ready') return this.history.latest;
    const prev = this.history.latest;
    const tick = prev.tick + 1;
    const ctx: TickContext = {
      world: this.worldInputs(prev.world, tick),
      previous: prev.tick === 0 ? null : prev.outputs,
      outputs: this.noOutputs.slice(),
      random: this.streams.length ? Object.freeze(this.streams.map((s) => s.next())) : EMPTY,
    };
    const printed: OutputLine[] = [];
    let error: ControllerError | null = null;
    const order = this.order;
    for (let k = 0; k < order.length; k++) {
      error = this.runFunction(order[k], ctx, printed, tick);
      if (error) break;
    }
    let world = prev.world;
    if (!error) {
      const command = ctx.outputs[this.bodyIndex] as BodyCommand;
      world = applyCommand(prev.world, command, tick);
    }
    const record: TickRecord = Object.freeze({
      tick,
      world,
      outputs: Object.freeze(ctx.outputs),
      random: ctx.random,
      printed: printed.length ? Object.freeze(printed) : EMPTY,
      error,
      edits: EMPTY,
    });
    this.history.push(record);
    this.updateStatus(record);
    return record;
  }

  /** Runs until the plan is complete, the robot crashes, an error occurs, or `maxTicks` more ticks. */
  run(maxTicks: number): RunSummary {
    for (let n = 0; n < maxTicks && this.currentStatus === 'ready'; n++) this.step();
    return this.summary();
  }

  /**
   * Records that the next tick stopped with an error found outside the session: the fast engine's
   * watchdog stopped a call that a guard could not (a slow built-in), in a worker since replaced.
   * The tick keeps the world as it was (T9) and ends the run.
   */
  stopNextTick(error: Omit<ControllerError, 'tick'>): TickRecord {
    if (this.currentStatus !== 'ready') return this.history.latest;
    const prev = this.history.latest;
    const tick = prev.tick + 1;
    const record: TickRecord = Object.freeze({
      tick,
      world: prev.world,
      outputs: Object.freeze(this.noOutputs.slice()),
      random: this.streams.length ? Object.freeze(this.streams.map((s) => s.next())) : EMPTY,
      printed: EMPTY,
      error: Object.freeze({ ...error, tick }),
      edits: EMPTY,
    });
    this.history.push(record);
    this.updateStatus(record);
    return record;
  }

  /** Applies a user's edit to the world at the current tick (a drag while the robot runs). */
  editWorld(edit: WorldEdit): void {
    const latest = this.history.latest;
    const world = editState(latest.world, edit);
    this.history.replaceLatest(Object.freeze({ ...latest, world, edits: Object.freeze([...latest.edits, edit]) }));
    if (this.currentStatus === 'done' && !planComplete(world)) this.currentStatus = 'ready';
    this.updateStatus(this.history.latest);
  }

  /** The run so far, as the CLI's `--json` prints it. */
  summary(): RunSummary {
    const latest = this.history.latest;
    const w = latest.world;
    return {
      ticks: latest.tick,
      crashed: w.crash !== null,
      crashTick: w.crash?.tick ?? null,
      goals: w.plan.map((name, i) => ({ name, reachedTick: w.reached[i] ?? null })),
      error: latest.error?.message ?? null,
    };
  }

  /** Every arc's value at a tick, in the controller's order, and whether it changed since the tick before. */
  arcs(tick: number): ArcView[] {
    const record = this.history.at(tick);
    const before = tick > 0 ? this.history.at(tick - 1) : null;
    const valueAt = (t: number, i: number, j: number): unknown => this.arcValue(t, i, j);
    const out: ArcView[] = [];
    this.functions.forEach(({ fn }, i) =>
      fn.inputs.forEach((inp, j) => {
        const from = inp.from;
        const value = record.tick === 0 ? undefined : valueAt(tick, i, j);
        const old = before && before.tick > 0 ? valueAt(tick - 1, i, j) : undefined;
        out.push({
          from:
            from.kind === 'function' ? from.function : from.kind === 'previous' ? `previous.${from.function}` : from.kind === 'world' ? `world.${from.input}` : `random.${from.source}`,
          to: fn.name,
          input: inp.name,
          previousTick: from.kind === 'previous',
          value,
          changed: tick > 1 && !sameValue(value, old),
        });
      }),
    );
    return out;
  }

  /** The value input `j` of function `i` received at `tick` (tick >= 1). */
  arcValue(tick: number, i: number, j: number): unknown {
    const record = this.history.at(tick);
    const prev = this.history.at(tick - 1);
    return gather(this.plans[i][j], {
      world: this.worldInputs(prev.world, tick),
      previous: prev.tick === 0 ? null : prev.outputs,
      outputs: record.outputs as unknown[],
      random: record.random,
    });
  }

  /** Releases the sandboxes. */
  dispose(): void {
    this.sandbox.dispose();
    this.debugSandbox?.dispose();
  }

  private newStreams(): RandomStream[] {
    return createStreams(
      allRandomSources(this.controller).map((r) => r.source),
      this.options.seed,
    );
  }

  private firstRecord(): TickRecord {
    return Object.freeze({
      tick: 0,
      world: initialState(this.worldSpec),
      outputs: EMPTY,
      random: EMPTY,
      printed: EMPTY,
      error: null,
      edits: EMPTY,
    });
  }

  private updateStatus(record: TickRecord): void {
    if (record.error) this.currentStatus = 'error';
    else if (record.world.crash) this.currentStatus = 'crashed';
    else if (record.world.plan.length > 0 && planComplete(record.world)) this.currentStatus = 'done';
  }

  private argPlan(from: ControllerSpec['layers'][number]['functions'][number]['inputs'][number]['from']): ArgPlan {
    const indexOf = (name: string) => this.functions.findIndex((f) => f.fn.name === name);
    const plan = { index: -1, input: 'tick' as WorldInputName, initial: undefined as unknown };
    switch (from.kind) {
      case 'function':
        return { ...plan, from: From.Function, index: indexOf(from.function) };
      case 'previous':
        return { ...plan, from: From.Previous, index: indexOf(from.function), initial: deepFreeze(structuredCloneJson(from.initial)) };
      case 'world':
        return { ...plan, from: From.World, input: from.input };
      case 'random':
        return { ...plan, from: From.Random, index: allRandomSources(this.controller).findIndex((r) => r.source.name === from.source) };
    }
  }

  /** World inputs for `tick`, read from the world after the previous tick; unchanged parts shared. */
  private worldInputs(world: WorldState, tick: number): Readonly<Record<WorldInputName, unknown>> {
    const c = this.inputsCache;
    if (c && c.world === world && c.tick === tick) return c.inputs;
    let pos = this.robotPosCache?.robot === world.robot ? this.robotPosCache.pos : null;
    if (!pos) {
      pos = Object.freeze([world.robot.x, world.robot.y]) as Point;
      this.robotPosCache = { robot: world.robot, pos };
    }
    const inputs = Object.freeze({
      robotPos: pos,
      heading: world.robot.heading,
      whisker: world.whisker,
      walls: world.walls,
      goals: world.goals,
      plan: world.plan,
      tick,
      crashed: world.crash !== null,
    });
    this.inputsCache = { world, tick, inputs };
    return inputs;
  }

  /** Runs function `i`; returns the error that stops the tick, or null. */
  private runFunction(i: number, ctx: TickContext, printed: OutputLine[], tick: number): ControllerError | null {
    const { fn, layer } = this.functions[i];
    const plans = this.plans[i];
    // Built by appending: a list made by `new Array(n)` is "holey", and reading holey lists is
    // several times slower in the fast engine's locked-down realm.
    const args: unknown[] = [];
    for (let j = 0; j < plans.length; j++) args.push(gather(plans[j], ctx));
    // Functions are pure (T12): called with the very same inputs as on its last call, a function
    // returns the same value and prints the same lines, so the call is not made again.
    const last = this.lastCalls[i];
    if (last !== null && sameArgs(last.args, args)) {
      for (let k = 0; k < last.output.length; k++) printed.push({ function: fn.name, layer: layer.name, text: last.output[k] });
      ctx.outputs[i] = last.value;
      return null;
    }
    const result = this.sandbox.call(i, args, this.budget);
    if (result.output.length) for (const text of result.output) printed.push({ function: fn.name, layer: layer.name, text });
    if (!result.ok) return this.failure(i, args, result, tick);
    if (!matchesType(result.value, fn.output)) {
      return {
        tick,
        function: fn.name,
        layer: layer.name,
        blockId: null,
        kind: 'type',
        message: functionErrorMessage(
          fn.name,
          layer.name,
          `it should return ${VALUE_TYPE_LABELS[fn.output]}, but it returned ${describeValue(result.value)}${result.value === undefined ? '' : ` (${formatValue(result.value, 60)})`}.`,
        ),
      };
    }
    // A value equal to this function's previous output is stored as that same object, so the
    // history holds each value once while it is unchanged, whatever the function's code does;
    // a new value shares its small lists with earlier outputs (intern.ts).
    const before = ctx.previous?.[i];
    const value = before !== undefined && before !== result.value && sameValue(before, result.value) ? before : args.includes(result.value) ? result.value : this.cells.intern(result.value);
    ctx.outputs[i] = value;
    this.lastCalls[i] = { args, value, output: result.output };
    return null;
  }

  /** Builds the error for a failed call, finding the failing block by replaying the call instrumented. */
  private failure(i: number, args: readonly unknown[], result: SandboxFailure, tick: number): ControllerError {
    const { fn, layer } = this.functions[i];
    let blockId = result.blockId;
    if (blockId === null && this.compiled[i].debugSource) {
      this.debugSandbox ??= this.options.sandbox(this.compiled.map((c) => ({ ...c, source: c.debugSource ?? c.source })));
      const replay = this.debugSandbox.call(i, args, this.budget);
      if (!replay.ok) blockId = replay.blockId;
    }
    return {
      tick,
      function: fn.name,
      layer: layer.name,
      blockId,
      kind: result.kind,
      message: functionErrorMessage(fn.name, layer.name, result.message),
    };
  }
}

interface LastCall {
  readonly args: readonly unknown[];
  readonly value: unknown;
  readonly output: readonly string[];
}

/** True when two argument lists hold the same values: the same objects, equal primitives. */
function sameArgs(a: readonly unknown[], b: readonly unknown[]): boolean {
  for (let j = 0; j < a.length; j++) if (!Object.is(a[j], b[j])) return false;
  return true;
}

/** The value of one argument at a tick. */
function gather(p: ArgPlan, ctx: TickContext): unknown {
  switch (p.from) {
    case From.Function:
      return ctx.outputs[p.index];
    case From.Previous:
      return ctx.previous ? ctx.previous[p.index] : p.initial;
    case From.World:
      return ctx.world[p.input];
    case From.Random:
      return ctx.random[p.index];
  }
}

function structuredCloneJson<T>(v: T): T {
  return v === undefined ? v : (JSON.parse(JSON.stringify(v)) as T);
}
