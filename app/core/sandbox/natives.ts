/**
 * The native functions a sandbox binds in its interpreter: `print`, `__block` and every helper of
 * the API table. Helpers see native values (inputs reach them unconverted, through the reverse
 * map) and their results come back as fresh, mutable pseudo values.
 */
import Interpreter from 'js-interpreter';
import { describeValue, matchesType, VALUE_TYPE_LABELS } from '../values';
import type { ApiEntry } from './api';
import { API } from './api';
import type { Converter } from './convert';
import { formatCount, ValueProblem } from './convert';

type Value = Interpreter.Value;
const PseudoObject = Interpreter.Object;

/** What the natives record during one call; the sandbox resets it before each call. */
export interface CallRecord {
  output: string[];
  outputChars: number;
  /** Set once the output limits are reached: later lines are dropped. */
  full: boolean;
  /** The id passed to the latest `__block` call. */
  block: string | null;
  /** How many `__block` calls the call made (the stepper watches it to stop at blocks). */
  blockCalls: number;
}

/** Printing in a runaway loop must not fill the host's memory or the history. */
export const OUTPUT_LIMITS = { maxLines: 1_000, maxChars: 1_000_000 };

/**
 * Stops a call from inside the interpreter. Thrown as a host exception, it passes every
 * try/catch of the student code: running out of resources cannot be caught and ignored.
 */
export class Abort {
  constructor(
    readonly kind: 'budget' | 'resources',
    readonly message: string,
  ) {}
}

/** Binds `print`, `__block` and the API helpers on the interpreter's global object. */
export function bindNatives(it: Interpreter, conv: Converter, record: CallRecord): void {
  const bind = (name: string, fn: (this: Value, ...args: Value[]) => Value): void => {
    Object.defineProperty(fn, 'name', { value: name });
    it.setProperty(it.globalObject, name, it.createNativeFunction(fn, false), Interpreter.NONENUMERABLE_DESCRIPTOR);
  };
  bind('print', (x) => {
    print(record, textOf(conv, x));
    return undefined;
  });
  bind('__block', (id) => {
    record.block = typeof id === 'string' ? id : String(id);
    record.blockCalls++;
    return undefined;
  });
  for (const [name, entry] of Object.entries(API) as [string, ApiEntry][]) bind(name, helper(it, conv, name, entry));
}

function print(record: CallRecord, text: string): void {
  if (record.full) return;
  const { maxLines, maxChars } = OUTPUT_LIMITS;
  const room = maxChars - record.outputChars;
  if (record.output.length === maxLines || room <= 0) {
    record.full = true;
    record.output.push(`… (it printed more than ${formatCount(maxLines)} lines or ${formatCount(maxChars)} characters; the rest is not shown)`);
    return;
  }
  const line = text.length > room ? `${text.slice(0, room)}…` : text;
  record.outputChars += line.length;
  record.output.push(line);
}

/** What `print` shows: texts as they are, lists and records as JSON. */
function textOf(conv: Converter, x: Value): string {
  if (typeof x === 'string') return x;
  if (!(x instanceof PseudoObject)) return String(x);
  if (x.class === 'Function') return '[function]';
  try {
    return JSON.stringify(conv.toNative(x)) ?? 'undefined';
  } catch (e) {
    if (e instanceof ValueProblem && e.kind === 'resources') throw new Abort('resources', `it printed a value that is too large: ${e.message}.`);
    return `[a value that cannot be printed: ${e instanceof Error ? e.message : String(e)}]`;
  }
}

/** Wraps one API helper: checks and converts its arguments, converts its result back. */
function helper(it: Interpreter, conv: Converter, name: string, entry: ApiEntry): (this: Value, ...args: Value[]) => Value {
  const fn = entry.fn as (...args: unknown[]) => unknown;
  const params = entry.params;
  return (...args) => {
    const natives = new Array<unknown>(params.length);
    for (let i = 0; i < params.length; i++) {
      const p = params[i];
      let v: unknown;
      try {
        v = conv.toNative(args[i]);
      } catch (e) {
        if (!(e instanceof ValueProblem)) throw e;
        if (e.kind === 'resources') throw new Abort('resources', `it passed a value that is too large to ${name}: ${e.message}.`);
        it.throwException(it.TYPE_ERROR, `${name}: its input "${p.name}" cannot be used: ${e.message}.`);
      }
      if (!matchesType(v, p.type)) {
        it.throwException(it.TYPE_ERROR, `${name}: its input "${p.name}" should be ${VALUE_TYPE_LABELS[p.type]}, but it is ${v === undefined ? 'undefined' : describeValue(v)}.`);
      }
      natives[i] = v;
    }
    let result: unknown;
    try {
      result = fn(...natives);
    } catch (e) {
      it.throwException(e instanceof RangeError ? it.RANGE_ERROR : it.TYPE_ERROR, `${name}: ${e instanceof Error ? e.message : String(e)}`);
    }
    return conv.toLocal(result);
  };
}
