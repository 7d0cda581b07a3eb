/**
 * "Step into": replays one function call block by block in JS-Interpreter. Functions are pure
 * (SPEC T12), so a call with the inputs a function received at tick t reproduces what it did at
 * tick t exactly: the same result, the same printed lines, the same error.
 *
 * The stepper runs the function's debug source (a `__block("id");` marker before each block's
 * statement) in an ordinary interpreter sandbox, so it shares every rule of a run: the same
 * natives, read-only inputs, locked built-ins, limits and messages. The markers' own steps are not
 * counted, so the step budget is spent exactly as in a run of the plain source.
 *
 * Where a step stops (a "block" is a statement block: the marker before it has just run):
 * - `stepBlock` (Step): runs the current block and stops at the next block that runs in the same
 *   call of the same function, or in its caller once it returns. Blocks nested in an if or a loop
 *   of that function count; blocks inside helper procedures it calls run without stopping. A loop
 *   block is stopped at again before each further round.
 * - `stepInto`: stops at the very next block that runs, wherever it is: inside a helper procedure
 *   the current block calls, if any; otherwise it is the same as `stepBlock`.
 * - `stepOut`: finishes the current helper procedure and stops at the next block of its caller;
 *   at the function's own level, runs to the end.
 * - `continue`: runs to the end.
 * Each returns `current()`. `start(kind)` + `run(maxSteps)` do the same in slices, so a page can
 * keep drawing while a long loop runs (`busy` says the step has not reached its stop yet).
 */
import Interpreter from 'js-interpreter';
import type { ValueType } from '../values';
import { describeValue, formatValue, matchesType, VALUE_TYPE_LABELS } from '../values';
import { ValueProblem } from './convert';
import type { SandboxInternals } from './interpreter';
import { InterpreterSandbox } from './interpreter';
import type { CompiledFunction, SandboxResult } from './types';
import { functionErrorMessage } from './types';

type Obj = Interpreter.Object;
/** Read once: with bundlers' interop, `Interpreter.Object` may be a getter on every access. */
const PseudoObject = Interpreter.Object;

export type StepKind = 'block' | 'into' | 'out' | 'end';

export interface StepperOptions {
  /** The function; its `debugSource` is replayed (a text-mode function has none: it runs in one go). */
  readonly fn: CompiledFunction;
  /** The inputs it received, in the order of `fn.params`. */
  readonly args: readonly unknown[];
  /** The controller's step budget per call. */
  readonly budget: number;
  /** The declared output type: a result of another type is the run's type error. */
  readonly output?: ValueType;
  /** Names of the layer's variables (to tell them apart from block variables). */
  readonly layerVariables?: readonly string[];
}

/** What a name in a frame is: an input of the function, a layer variable, a block variable, a helper's parameter. */
export type LocalKind = 'input' | 'layer' | 'variable' | 'parameter';

export interface Local {
  readonly name: string;
  readonly kind: LocalKind;
  /** The value as a native value (undefined: not set yet). */
  readonly value: unknown;
  /** Set when the value cannot be shown as data (it holds a function, say). */
  readonly problem?: string;
}

/** One function call on the way to the current block: the function itself, or a helper procedure. */
export interface StepFrame {
  readonly function: string;
  readonly locals: readonly Local[];
}

export interface StepError {
  readonly kind: string;
  /** The full message, as a run reports it: `Error in function "F" (layer "L"): ...`. */
  readonly message: string;
  readonly blockId: string | null;
}

export interface StepView {
  readonly function: string;
  readonly layer: string;
  /** The block about to run; null before the first block and once the call has ended. */
  readonly blockId: string | null;
  /** The block's first line in `listing.lines`, when known. */
  readonly line: number | null;
  /** The call has ended (returned or failed). */
  readonly done: boolean;
  /** A step is under way and has not reached its stop (only after `run` with a step limit). */
  readonly busy: boolean;
  /** The returned value, once done without an error. */
  readonly result?: unknown;
  readonly error?: StepError;
  /** Lines printed so far. */
  readonly printed: readonly string[];
  /** The variables of the innermost call (= `frames[0].locals`). */
  readonly locals: readonly Local[];
  /** Calls from the innermost (a helper procedure) to the function itself. */
  readonly frames: readonly StepFrame[];
  /** Blocks started so far. */
  readonly blocks: number;
  /** Steps counted against the budget so far. */
  readonly steps: number;
}

/** The code a student reads: the debug source without its markers, and where each block starts. */
export interface Listing {
  readonly lines: readonly string[];
  /** Each block id's first statement line (a loop's marker repeats at the end of its body). */
  readonly blockLines: ReadonlyMap<string, number>;
}

const MARKER = /^\s*__block\((.*)\);\s*$/;

/** Splits a debug source into the lines to show and each block's line. */
export function debugListing(debugSource: string): Listing {
  const lines: string[] = [];
  const blockLines = new Map<string, number>();
  for (const line of debugSource.split('\n')) {
    const m = MARKER.exec(line);
    if (!m) {
      lines.push(line);
      continue;
    }
    const id = markerId(m[1]);
    if (id !== null && !blockLines.has(id)) blockLines.set(id, lines.length);
  }
  return { lines, blockLines };
}

/** The id in a marker's argument: a quoted string literal, as Blockly writes it. */
function markerId(literal: string): string | null {
  const q = literal[0];
  if ((q !== "'" && q !== '"') || literal[literal.length - 1] !== q) return null;
  return literal.slice(1, -1).replace(/\\(.)/g, '$1');
}

export class Stepper {
  readonly listing: Listing;
  private readonly sandbox: InterpreterSandbox;
  private readonly inner: SandboxInternals;
  private readonly free: Set<Interpreter.Node>;
  private readonly inputs: ReadonlySet<string>;
  private readonly layerVars: ReadonlySet<string>;
  private result: SandboxResult | null = null;
  private goal: { kind: StepKind; depth: number } | null = null;
  private seenBlocks = 0;
  private blockId: string | null = null;
  private disposed = false;

  /** Creates the interpreter and begins the call, before its first block (throws CompileError on a syntax error). */
  constructor(private readonly options: StepperOptions) {
    const { fn } = options;
    const source = fn.debugSource ?? fn.source;
    this.listing = debugListing(source);
    this.sandbox = new InterpreterSandbox([{ ...fn, source }]);
    this.inner = this.sandbox.internals;
    this.free = markerNodes(this.inner.functionNode(0).node as Interpreter.Node);
    this.inputs = new Set(fn.params);
    this.layerVars = new Set(options.layerVariables ?? []);
    this.sandbox.begin(0, options.args, options.budget);
  }

  /** Starts the call again from the beginning (before its first block). */
  restart(): StepView {
    this.alive();
    this.result = null;
    this.goal = null;
    this.seenBlocks = 0;
    this.blockId = null;
    this.sandbox.begin(0, this.options.args, this.options.budget);
    return this.current();
  }

  stepBlock(): StepView {
    return this.whole('block');
  }

  stepInto(): StepView {
    return this.whole('into');
  }

  stepOut(): StepView {
    return this.whole('out');
  }

  continue(): StepView {
    return this.whole('end');
  }

  /** Sets the next step's kind (replacing one still under way); `run` carries it out. */
  start(kind: StepKind): void {
    this.alive();
    if (this.result) return;
    this.goal = { kind, depth: this.depth() };
  }

  /** Works on the step begun with `start` for at most `maxSteps` interpreter steps. */
  run(maxSteps = Infinity): StepView {
    this.alive();
    const goal = this.goal;
    if (this.result || !goal) return this.current();
    const record = this.inner.record;
    let left = maxSteps;
    let sliceEnded = false;
    let reached = false;
    const r = this.sandbox.resume({
      free: this.free,
      pause: () => {
        if (record.blockCalls !== this.seenBlocks) {
          this.seenBlocks = record.blockCalls;
          this.blockId = record.block;
          if (this.stopsHere(goal)) return (reached = true);
        }
        if (--left <= 0) return (sliceEnded = true);
        return false;
      },
    });
    if (r) {
      this.result = r;
      this.blockId = null;
    }
    if (r || reached || !sliceEnded) this.goal = null;
    return this.current();
  }

  /** Where the call is now. */
  current(): StepView {
    this.alive();
    const { fn } = this.options;
    const r = this.result;
    const base = {
      function: fn.name,
      layer: fn.layer,
      blocks: this.seenBlocks,
      busy: this.goal !== null && r === null,
    };
    if (r) {
      const frames: StepFrame[] = [];
      const common = { ...base, blockId: null, line: null, done: true, printed: [...r.output], locals: [], frames, steps: r.ok ? r.steps : this.inner.steps() };
      if (!r.ok) return { ...common, error: { kind: r.kind, message: this.message(r.message), blockId: r.blockId } };
      const type = this.options.output;
      if (type !== undefined && !matchesType(r.value, type)) return { ...common, error: { kind: 'type', message: this.typeMessage(r.value, type), blockId: null } };
      return { ...common, result: r.value };
    }
    const frames = this.frames();
    const id = this.blockId;
    return {
      ...base,
      blockId: id,
      line: id === null ? null : (this.listing.blockLines.get(id) ?? null),
      done: false,
      printed: [...this.inner.record.output],
      locals: frames[0]?.locals ?? [],
      frames,
      steps: this.inner.steps(),
    };
  }

  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.sandbox.dispose();
  }

  private whole(kind: StepKind): StepView {
    this.start(kind);
    return this.run();
  }

  private alive(): void {
    if (this.disposed) throw new Error('This stepper has been disposed.');
  }

  private stopsHere(goal: { kind: StepKind; depth: number }): boolean {
    switch (goal.kind) {
      case 'into':
        return true;
      case 'block':
        return goal.depth === 0 || this.depth() <= goal.depth;
      case 'out':
        return this.depth() < goal.depth;
      case 'end':
        return false;
    }
  }

  /** The interpreted calls on the stack, outermost first (native calls finish within one step). */
  private calls(): { state: Interpreter.State; body: Interpreter.State | undefined }[] {
    const stack = this.inner.interpreter.stateStack;
    const out: { state: Interpreter.State; body: Interpreter.State | undefined }[] = [];
    for (let i = 1; i < stack.length; i++) {
      const s = stack[i];
      if (s.node.type !== 'CallExpression' && s.node.type !== 'NewExpression') continue;
      const f = s['func_'];
      if (f instanceof PseudoObject && f.node !== undefined && s['doneExec_'] === true) out.push({ state: s, body: stack[i + 1] });
    }
    return out;
  }

  private depth(): number {
    return this.calls().length;
  }

  /** The variables of each call, innermost first. */
  private frames(): StepFrame[] {
    const conv = this.inner.converter;
    const calls = this.calls();
    const frames: StepFrame[] = [];
    calls.forEach(({ state, body }, i) => {
      const func = state['func_'] as Obj;
      const outer = i === 0;
      const name = outer ? this.options.fn.name : ((func.node?.id as { name?: string } | null | undefined)?.name ?? 'helper');
      if (!body) return frames.unshift({ function: name, locals: [] });
      const params = new Set(((func.node?.['params'] as { name: string }[] | undefined) ?? []).map((p) => p.name));
      const props = body.scope.object.properties;
      const locals: Local[] = [];
      for (const key of Object.keys(props)) {
        if (key === 'arguments' || key === 'this') continue;
        const v = props[key];
        if (v instanceof PseudoObject && v.class === 'Function') continue;
        const kind: LocalKind = outer ? (this.inputs.has(key) ? 'input' : this.layerVars.has(key) ? 'layer' : 'variable') : params.has(key) ? 'parameter' : 'variable';
        try {
          locals.push({ name: key, kind, value: conv.toNative(v) });
        } catch (e) {
          if (!(e instanceof ValueProblem)) throw e;
          locals.push({ name: key, kind, value: undefined, problem: e.message });
        }
      }
      const rank: Record<LocalKind, number> = { input: 0, parameter: 0, layer: 1, variable: 2 };
      locals.sort((a, b) => rank[a.kind] - rank[b.kind]);
      frames.unshift({ function: name, locals });
    });
    return frames;
  }

  private message(detail: string): string {
    const { fn } = this.options;
    return functionErrorMessage(fn.name, fn.layer, detail);
  }

  /** The run's message for a result of the wrong type (Session.runFunction words it the same). */
  private typeMessage(value: unknown, type: ValueType): string {
    return this.message(
      `it should return ${VALUE_TYPE_LABELS[type]}, but it returned ${describeValue(value)}${value === undefined ? '' : ` (${formatValue(value, 60)})`}.`,
    );
  }
}

/** Every node of the `__block(...)` marker statements in a function's AST. */
function markerNodes(root: Interpreter.Node): Set<Interpreter.Node> {
  const free = new Set<Interpreter.Node>();
  const addAll = (n: Interpreter.Node): void => {
    free.add(n);
    forChildren(n, addAll);
  };
  const visit = (n: Interpreter.Node): void => {
    if (isMarker(n)) return addAll(n);
    forChildren(n, visit);
  };
  visit(root);
  return free;
}

function isMarker(n: Interpreter.Node): boolean {
  if (n.type !== 'ExpressionStatement') return false;
  const e = n['expression'] as Interpreter.Node | undefined;
  const callee = e?.['callee'] as Interpreter.Node | undefined;
  return e?.type === 'CallExpression' && callee?.type === 'Identifier' && callee['name'] === '__block';
}

function forChildren(n: Interpreter.Node, fn: (child: Interpreter.Node) => void): void {
  for (const key of Object.keys(n)) {
    const v = (n as Record<string, unknown>)[key];
    if (Array.isArray(v)) {
      for (const c of v) if (isNode(c)) fn(c);
    } else if (isNode(v)) fn(v);
  }
}

function isNode(v: unknown): v is Interpreter.Node {
  return typeof v === 'object' && v !== null && typeof (v as { type?: unknown }).type === 'string' && !Array.isArray(v);
}
