/**
 * The reference sandbox engine: JS-Interpreter. One interpreter holds all functions of a
 * controller, declared once; a call pushes a ready-made CallExpression state onto the
 * interpreter's state stack (no parsing per call) and steps it, counting steps against the budget.
 *
 * Relies on library internals (state fields of stepCallExpression, the state stack, setProperty):
 * js-interpreter is pinned at 6.0.2 and tests/unit/sandbox guards the behaviour.
 */
import Interpreter from 'js-interpreter';
import { deepFreeze } from '../values';
import { Converter, formatCount, ValueProblem } from './convert';
import type { CallRecord } from './natives';
import { Abort, bindNatives } from './natives';
import { createInterpreter, guardWrites, lockGraph } from './setup';
import type { CompiledFunction, Sandbox, SandboxFactory, SandboxFailure, SandboxFailureKind, SandboxResult } from './types';
import { CompileError } from './types';

type Obj = Interpreter.Object;
/** Read once: with bundlers' interop, `Interpreter.State` may be a getter on every access. */
const State = Interpreter.State;

/** Limits that keep runaway code from exhausting the host. */
export const RUN_LIMITS = {
  /** Interpreter states (about 6 per nested call of a small function): deep recursion. */
  maxStackStates: 30_000,
  /** Characters in one text value: a text doubled in a loop. */
  maxStringLength: 1_000_000,
};

/**
 * The message of the TypeError raised inside the interpreter when code writes to an input. The
 * student's code may catch it; if it does not, the call fails with kind 'mutation'.
 */
const MUTATION_TEXT = 'Cannot change an input: inputs are read-only. Make a copy first and change the copy.';

/** Hooks of `resume` for a call run in pieces (the stepper). */
export interface ResumeHooks {
  /** Asked after every step while the call runs: true pauses it. */
  pause(): boolean;
  /** Nodes whose steps are not counted (the `__block` markers and everything inside them). */
  readonly free?: ReadonlySet<Interpreter.Node>;
}

/** The parts of a sandbox the stepper reads between steps (never changes). */
export interface SandboxInternals {
  readonly interpreter: Interpreter;
  readonly converter: Converter;
  readonly record: CallRecord;
  /** The pseudo function object of function number `index` (its `node` and `parentScope`). */
  functionNode(index: number): Obj;
  /** Steps counted so far in the active call. */
  steps(): number;
}

interface ActiveCall {
  readonly d: Declared;
  readonly args: readonly unknown[];
  readonly budget: number;
  steps: number;
}

interface Declared {
  readonly fn: CompiledFunction;
  readonly func: Obj;
  readonly callNode: Interpreter.Node;
}

/** Creates a JS-Interpreter sandbox holding `functions`; throws CompileError for a syntax error. */
export const createInterpreterSandbox: SandboxFactory = (functions) => new InterpreterSandbox(functions);

export class InterpreterSandbox implements Sandbox {
  private it: Interpreter | null;
  private readonly conv: Converter;
  private readonly declared: Declared[];
  private readonly record: CallRecord = { output: [], outputChars: 0, full: false, block: null, blockCalls: 0 };
  private active: ActiveCall | null = null;
  /** The input the latest guarded write targeted (to name it in the message). */
  private mutated: Obj | null = null;
  private calls = 0;
  /** Calls per cache generation: at least two ticks' worth, so values used every tick stay. */
  private readonly generation: number;

  constructor(functions: readonly CompiledFunction[]) {
    // Parse first: a syntax error is reported before paying for an interpreter.
    const asts = functions.map(parse);
    const it = createInterpreter();
    this.it = it;
    this.conv = new Converter(it);
    this.generation = Math.max(8, 2 * functions.length);
    bindNatives(it, this.conv, this.record);
    const scopes: Obj[] = [];
    this.declared = functions.map((fn, i) => {
      // Each function gets its own scope below the global one: functions cannot see or clobber
      // each other (two layers may even use the same name), and recursion by name works.
      const scope = it.createScope(asts[i].program, it.globalScope);
      scopes.push(scope.object);
      const func = scope.object.properties[asts[i].name] as Obj;
      // `end` is set because step() runs position-less nodes (its polyfills) as one batch; the
      // callee is only used by the library's error messages.
      const callNode: Interpreter.Node = { type: 'CallExpression', callee: { type: 'Identifier', name: asts[i].name }, arguments: [], start: 0, end: 1 };
      return { fn, func, callNode };
    });
    const locked = new WeakSet<Obj>();
    lockGraph([it.globalObject, ...scopes], locked);
    guardWrites(it, (obj, name) => {
      if (this.conv.isInput(obj)) {
        this.mutated = obj;
        it.throwException(it.TYPE_ERROR, MUTATION_TEXT);
      }
      if (locked.has(obj)) it.throwException(it.TYPE_ERROR, `Cannot change "${name}": built-in values and functions are read-only.`);
    });
  }

  call(index: number, args: readonly unknown[], budget: number): SandboxResult {
    this.begin(index, args, budget);
    return this.resume(null) as SandboxResult;
  }

  /**
   * Starts a call without running it: `resume` runs it. `call` is `begin` + `resume(null)`; the
   * stepper (stepper.ts) resumes with hooks to stop at blocks. One call is active at a time.
   */
  begin(index: number, args: readonly unknown[], budget: number): void {
    const it = this.it;
    if (!it) throw new Error('This sandbox has been disposed.');
    const d = this.declared[index];
    if (!d) throw new RangeError(`There is no function number ${index}.`);
    if (!(budget >= 0)) throw new RangeError(`The step budget must be a number >= 0, not ${budget}.`);
    if (++this.calls % this.generation === 0) this.conv.rotate();
    const record = this.record;
    record.output = [];
    record.outputChars = 0;
    record.full = false;
    record.block = null;
    record.blockCalls = 0;
    this.mutated = null;
    if (this.active) this.reset(it);

    const state = new State(d.callNode, it.globalScope);
    // A CallExpression whose callee and arguments are already evaluated (see stepCallExpression).
    state['doneCallee_'] = 2;
    state['func_'] = d.func;
    state['funcThis_'] = undefined;
    state['arguments_'] = args.map((a) => this.conv.toInput(a));
    state['n_'] = 0;
    state['doneArgs_'] = true;
    it.stateStack.push(state);
    this.active = { d, args, budget, steps: 0 };
  }

  /**
   * Runs the active call until it ends (returns its result) or, with hooks, until `hooks.pause()`
   * (asked after each step) says to stop (returns null; resume again to go on). Steps on `free`
   * nodes, and steps that push one, do not count against the budget: the stepper's `__block`
   * markers then cost nothing, so a replay counts exactly the steps of the run.
   */
  resume(hooks: ResumeHooks | null): SandboxResult | null {
    const it = this.it;
    const call = this.active;
    if (!it || !call) throw new Error('There is no call to resume.');
    const { d, args, budget } = call;
    const stack = it.stateStack;
    const { maxStackStates, maxStringLength } = RUN_LIMITS;
    const free = hooks?.free ?? null;
    let steps = call.steps;
    let returned: unknown;
    try {
      while (stack.length > 1) {
        if (steps >= budget) throw new Abort('budget', `it ran for more than ${formatCount(budget)} steps without finishing. Check its loops: is there one that never ends?`);
        if (free === null) {
          it.step();
          steps++;
        } else {
          const depth = stack.length;
          const counted = !free.has(stack[depth - 1].node);
          it.step();
          if (counted && !(stack.length === depth + 1 && free.has(stack[depth].node))) steps++;
        }
        if (stack.length > maxStackStates) {
          throw new Abort('resources', 'its calls went too deep. Check its recursion: does every recursive call get closer to a case that stops?');
        }
        // Every new value passes through the top state: checking it catches a text doubled in a
        // loop long before it reaches the host's limits.
        const v = stack[stack.length - 1].value;
        if (typeof v === 'string' && v.length > maxStringLength) {
          throw new Abort('resources', `it made a text longer than ${formatCount(maxStringLength)} characters.`);
        }
        if (hooks !== null && stack.length > 1 && hooks.pause()) {
          call.steps = steps;
          return null;
        }
      }
      returned = stack[0].value;
    } catch (e) {
      this.active = null;
      call.steps = steps;
      const failure = this.failure(e, it, d, args);
      this.reset(it);
      return failure;
    }
    this.active = null;
    call.steps = steps;
    stack[0].value = undefined;
    try {
      return { ok: true, value: deepFreeze(this.conv.toNative(returned as Interpreter.Value)), output: this.record.output, steps };
    } catch (e) {
      if (!(e instanceof ValueProblem)) throw e;
      return this.fail(e.kind, `it returned a value that cannot be kept: ${e.message}.`);
    }
  }

  /** What the stepper reads between steps: the interpreter, the converter, the active call. */
  get internals(): SandboxInternals {
    if (!this.it) throw new Error('This sandbox has been disposed.');
    return {
      interpreter: this.it,
      converter: this.conv,
      record: this.record,
      functionNode: (index) => this.declared[index].func,
      steps: () => this.active?.steps ?? 0,
    };
  }

  dispose(): void {
    this.it = null;
    this.active = null;
    this.conv.clear();
  }

  private fail(kind: SandboxFailureKind, message: string): SandboxFailure {
    return { ok: false, kind, message, output: this.record.output, blockId: this.record.block };
  }

  /** Classifies what stopped a call. */
  private failure(e: unknown, it: Interpreter, d: Declared, args: readonly unknown[]): SandboxFailure {
    if (e instanceof Abort) return this.fail(e.kind, e.message);
    if (e !== it.value) {
      // Not the student's exception (those are what the library stores in `value`): the host
      // ran out of something (stack, string or array length) or the library failed.
      if (e instanceof RangeError) return this.fail('resources', `it needed more memory than a function may use (${e.message}).`);
      return this.fail('exception', `the sandbox could not run it (${e instanceof Error ? e.message : String(e)}).`);
    }
    if (e instanceof TypeError && e.message === MUTATION_TEXT && this.mutated) {
      const name = inputName(this.conv.nativeOf(this.mutated), d.fn.params, args);
      const what = name === null ? 'one of its inputs' : `its input "${name}"`;
      return this.fail('mutation', `it tried to change ${what}. Inputs cannot be changed: make a copy first (the "copy list" block) and change the copy.`);
    }
    if (e instanceof Error) return this.fail('exception', e.name === 'Error' ? e.message : `${e.name}: ${e.message}`);
    return this.fail('exception', `it threw ${String(e)}`);
  }

  /** Leaves the interpreter ready for the next call after a failed one. */
  private reset(it: Interpreter): void {
    const stack = it.stateStack;
    stack.length = 1;
    stack[0].value = undefined;
    stack[0].done = false;
    it.value = undefined;
    it.getterStep_ = false;
    it.setterStep_ = false;
    it.paused_ = false;
    Interpreter.toStringCycles_.length = 0;
  }
}

/** Parses one function's source on its own, so that a syntax error names the function. */
function parse(fn: CompiledFunction): { program: Interpreter.Node; name: string } {
  let program: Interpreter.Node;
  try {
    // parse_ uses no instance state: no interpreter is needed yet.
    program = Interpreter.prototype.parse_.call(undefined as never, fn.source, fn.name);
  } catch (e) {
    const text = e instanceof Error ? e.message.replace(/\s*\((\d+):(\d+)\)$/, ' (line $1, column $2)') : String(e);
    throw new CompileError(fn.name, fn.layer, `its code has a syntax error: ${text}.`);
  }
  const decls = (program.body as Interpreter.Node[]).filter((n) => n.type === 'FunctionDeclaration');
  const decl = decls.find((n) => n.id?.name === fn.name) ?? decls[0];
  if (!decl?.id) throw new CompileError(fn.name, fn.layer, 'its code is not a function declaration.');
  return { program, name: decl.id.name };
}

/** The parameter whose argument is, or holds, `target`. */
function inputName(target: object | undefined, params: readonly string[], args: readonly unknown[]): string | null {
  if (target === undefined) return null;
  for (let i = 0; i < args.length && i < params.length; i++) if (holds(args[i], target, new Set())) return params[i];
  return null;
}

function holds(v: unknown, target: object, seen: Set<object>): boolean {
  if (v === target) return true;
  if (typeof v !== 'object' || v === null || seen.has(v)) return false;
  seen.add(v);
  return Object.values(v).some((x) => holds(x, target, seen));
}
