/**
 * The fast sandbox engine: student functions run as native code in an SES Compartment, at close
 * to plain JavaScript speed, with the same contract as the reference engine (interpreter.ts).
 *
 * - SES's `lockdown()` freezes the whole realm, so this engine runs in a dedicated worker: call
 *   `lockdownForSandbox()` once there, before creating sandboxes.
 * - The step budget is kept by guards spliced into the source (ses-instrument.ts). A guard cannot
 *   stop a slow native built-in (a catastrophic regular expression, a huge `repeat`): the host of
 *   the worker keeps a watchdog that terminates it (app/cli/fast-session.ts).
 * - Inputs are the native, deeply frozen values themselves: a write throws a TypeError in strict
 *   code, reported as a 'mutation' failure naming the input.
 * - Results are checked and deeply frozen in place (ses-values.ts); a returned input keeps its identity.
 */
import 'ses';
import type { ApiEntry } from './api';
import { API } from './api';
import { formatCount, ValueProblem } from './convert';
import { OUTPUT_LIMITS } from './natives';
import { declare, declaringSource, sandboxCompartment } from './ses-env';
import type { SesDeclared } from './ses-env';
import { instrument } from './ses-instrument';
import { mutationMessage } from './ses-mutation';
import { ValueChecker } from './ses-values';
import type { CompiledFunction, Sandbox, SandboxFactory, SandboxFailure, SandboxFailureKind, SandboxResult } from './types';
import { CompileError } from './types';
import { describeValue, matchesType, VALUE_TYPE_LABELS } from '../values';

/** The failure a guard or a hook throws; student code cannot catch it (catch blocks rethrow it). */
class Stop {
  constructor(
    readonly kind: 'budget' | 'resources',
    readonly message: string,
  ) {}
}

/**
 * Calls with an argument list. Never spread (`f(...args)`) on this engine's paths: `lockdown()`
 * freezes the array iterator's intrinsics, which turns V8's fast path for spreading off for the
 * whole realm; a spread call then costs about 250 ns against 30 ns for `Reflect.apply` (measured
 * with Node 20).
 */
const { apply } = Reflect;

/** The output of a call that printed nothing (shared, never written to). */
const NO_OUTPUT: string[] = Object.freeze([]) as unknown as string[];

const TOO_DEEP = 'its calls went too deep. Check its recursion: does every recursive call get closer to a case that stops?';

/**
 * Locks the realm down for the fast engine (once per worker). Errors keep their stacks for the
 * host's diagnostics; SES's own reports and traps are off: failures are values here.
 *
 * Override taming is 'min': 'moderate' turns `Array.prototype.push` and `[Symbol.iterator]` into
 * accessors, and V8 then takes its slow paths for every `push`, spread and `for...of` in the realm
 * (the basic controller ran at about half its speed). Code in this realm must not assign a
 * property its frozen prototype already has (the "override mistake"): define it instead.
 */
export function lockdownForSandbox(): void {
  if (isLockedDown()) return;
  lockdown({
    errorTaming: 'unsafe',
    consoleTaming: 'unsafe',
    overrideTaming: 'min',
    stackFiltering: 'verbose',
    errorTrapping: 'none',
    unhandledRejectionTrapping: 'none',
    reporting: 'none',
  });
}

function isLockedDown(): boolean {
  return Object.isFrozen(Array.prototype) && Object.isFrozen(Object.prototype);
}

/** Creates a fast sandbox holding `functions`; the realm must be locked down (see above). */
export const createSesSandbox: SandboxFactory = (functions) => new SesSandbox(functions);

interface CallRecord {
  output: string[];
  outputChars: number;
  full: boolean;
  block: string | null;
}

class SesSandbox implements Sandbox {
  private declared: SesDeclared | null;
  private readonly checker = new ValueChecker();
  private readonly record: CallRecord = { output: [], outputChars: 0, full: false, block: null };
  private stop: Stop | null = null;
  private budget = 0;

  constructor(private readonly functions: readonly CompiledFunction[]) {
    if (!isLockedDown()) throw new Error('The fast sandbox needs a locked-down realm: call lockdownForSandbox() first, in a dedicated worker.');
    const instrumented = functions.map(instrument);
    const c = sandboxCompartment();
    const natives: Record<string, (...args: never[]) => unknown> = {
      print: (x: unknown) => this.print(x),
      __block: (id: unknown) => {
        this.record.block = typeof id === 'string' ? id : String(id);
      },
    };
    for (const [name, entry] of Object.entries(API) as [string, ApiEntry][]) natives[name] = this.helper(name, entry);
    const env = {
      natives,
      over: (): never => {
        this.stop ??= new Stop('budget', `it ran for more than ${formatCount(this.budget)} steps without finishing. Check its loops: is there one that never ends?`);
        throw this.stop;
      },
      caught: (e: unknown): void => {
        if (this.stop) throw this.stop;
        if (isStackOverflow(e)) throw (this.stop = new Stop('resources', TOO_DEEP));
      },
    };
    try {
      this.declared = declare(c, declaringSource(instrumented), env);
    } catch (e) {
      // Something the parser accepted and V8 refuses (strict-mode rules): find the function.
      const i = instrumented.findIndex((f) => !evaluates(c, f.code));
      const fn = functions[Math.max(0, i)];
      throw new CompileError(fn.name, fn.layer, `its code cannot run: ${e instanceof Error ? e.message : String(e)}.`);
    }
  }

  call(index: number, args: readonly unknown[], budget: number): SandboxResult {
    const d = this.declared;
    if (!d) throw new Error('This sandbox has been disposed.');
    const fn = d.fns[index];
    if (!fn) throw new RangeError(`There is no function number ${index}.`);
    if (!(budget >= 0)) throw new RangeError(`The step budget must be a number >= 0, not ${budget}.`);
    const record = this.record;
    // Most calls print nothing: the list is made by the first print.
    record.output = NO_OUTPUT;
    record.outputChars = 0;
    record.full = false;
    record.block = null;
    this.stop = null;
    this.budget = budget;
    let value: unknown;
    let thrown: { e: unknown } | null = null;
    d.set(budget);
    try {
      value = apply(fn, undefined, args);
    } catch (e) {
      thrown = { e };
    }
    const left = d.get();
    // Nothing runs between calls: code left behind (a getter read while checking the result) stops at once.
    d.set(-1);
    // (Set by the guards and hooks during the call: TypeScript cannot see that.)
    const stop = this.stop as Stop | null;
    if (stop) return this.fail(stop.kind, stop.message);
    if (thrown) return this.failure(thrown.e, index, args);
    try {
      const steps = Number.isFinite(budget) ? Math.min(budget, budget - left) : 0;
      return { ok: true, value: this.checker.result(value), output: record.output, steps };
    } catch (e) {
      if (e instanceof ValueProblem) return this.fail(e.kind, `it returned a value that cannot be kept: ${e.message}.`);
      if (e instanceof Stop || this.stop) return this.fail('exception', 'it returned a value that cannot be kept: it holds a getter or setter.');
      return this.failure(e, index, args);
    }
  }

  dispose(): void {
    this.declared = null;
  }

  private fail(kind: SandboxFailureKind, message: string): SandboxFailure {
    return { ok: false, kind, message, output: this.record.output, blockId: this.record.block };
  }

  /** Classifies what the student's code threw. */
  private failure(e: unknown, index: number, args: readonly unknown[]): SandboxFailure {
    if (isStackOverflow(e)) return this.fail('resources', TOO_DEEP);
    if (e instanceof RangeError && /Invalid (string|array|typed array) length|allocation failed|out of memory/i.test(e.message)) {
      return this.fail('resources', `it needed more memory than a function may use (${e.message}).`);
    }
    if (e instanceof TypeError) {
      const m = mutationMessage(e.message, this.functions[index].params, args);
      if (m) return this.fail(m.kind, m.message);
    }
    if (e instanceof Error) return this.fail('exception', e.name === 'Error' ? e.message : `${e.name}: ${e.message}`);
    let text: string;
    try {
      text = String(e);
    } catch {
      text = 'a value that cannot be shown';
    }
    return this.fail('exception', `it threw ${text}`);
  }

  private print(x: unknown): void {
    const r = this.record;
    if (r.full) return;
    const text = this.textOf(x);
    const { maxLines, maxChars } = OUTPUT_LIMITS;
    const room = maxChars - r.outputChars;
    if (r.output.length === maxLines || room <= 0) {
      r.full = true;
      if (r.output === NO_OUTPUT) r.output = [];
      r.output.push(`… (it printed more than ${formatCount(maxLines)} lines or ${formatCount(maxChars)} characters; the rest is not shown)`);
      return;
    }
    const line = text.length > room ? `${text.slice(0, room)}…` : text;
    r.outputChars += line.length;
    if (r.output === NO_OUTPUT) r.output = [];
    r.output.push(line);
  }

  /** What `print` shows: texts as they are, lists and records as JSON (as the reference does). */
  private textOf(x: unknown): string {
    if (typeof x === 'string') return x;
    if (typeof x === 'function') return '[function]';
    if (typeof x !== 'object' || x === null) return String(x);
    try {
      return JSON.stringify(this.checker.argument(x)) ?? 'undefined';
    } catch (e) {
      if (e instanceof ValueProblem && e.kind === 'resources') throw (this.stop = new Stop('resources', `it printed a value that is too large: ${e.message}.`));
      if (e instanceof Stop) throw e;
      return `[a value that cannot be printed: ${e instanceof Error ? e.message : String(e)}]`;
    }
  }

  /** Wraps one API helper: checks its arguments as the reference does; errors worded the same. */
  private helper(name: string, entry: ApiEntry): (...args: never[]) => unknown {
    const fn = entry.fn as (...args: unknown[]) => unknown;
    const params = entry.params;
    const checker = this.checker;
    const check = (i: number, a: unknown): unknown => {
      const p = params[i];
      let v: unknown = a;
      if (typeof a === 'object' && a !== null) {
        try {
          v = checker.argument(a);
        } catch (e) {
          if (!(e instanceof ValueProblem)) throw e;
          if (e.kind === 'resources') throw (this.stop = new Stop('resources', `it passed a value that is too large to ${name}: ${e.message}.`));
          throw new TypeError(`${name}: its input "${p.name}" cannot be used: ${e.message}.`);
        }
      } else if (typeof a === 'function') {
        throw new TypeError(`${name}: its input "${p.name}" cannot be used: it is or holds a function.`);
      }
      if (!matchesType(v, p.type)) {
        throw new TypeError(`${name}: its input "${p.name}" should be ${VALUE_TYPE_LABELS[p.type]}, but it is ${v === undefined ? 'undefined' : describeValue(v)}.`);
      }
      return v;
    };
    const run = (args: unknown[]): unknown => {
      try {
        return apply(fn, undefined, args);
      } catch (e) {
        if (e instanceof Stop) throw e;
        const text = `${name}: ${e instanceof Error ? e.message : String(e)}`;
        throw e instanceof RangeError ? new RangeError(text) : new TypeError(text);
      }
    };
    // One wrapper per arity: a rest array and a spread per call cost more than the helper itself.
    switch (params.length) {
      case 0:
        return () => run([]);
      case 1:
        return (a?: unknown) => run([check(0, a)]);
      case 2:
        return (a?: unknown, b?: unknown) => run([check(0, a), check(1, b)]);
      case 3:
        return (a?: unknown, b?: unknown, c?: unknown) => run([check(0, a), check(1, b), check(2, c)]);
      default:
        return function (this: unknown) {
          // eslint-disable-next-line prefer-rest-params -- a rest parameter costs more here (see `apply`)
          const given = arguments;
          const args = new Array<unknown>(params.length);
          for (let i = 0; i < params.length; i++) args[i] = check(i, given[i]);
          return run(args);
        };
    }
  }
}

function isStackOverflow(e: unknown): boolean {
  return e instanceof RangeError && e.message.includes('Maximum call stack size exceeded');
}

function evaluates(c: Compartment, code: string): boolean {
  try {
    c.evaluate(`(function () {\n'use strict';\n${code}\n})`);
    return true;
  } catch {
    return false;
  }
}
