/**
 * The compartment a fast sandbox runs in, and the source that declares its functions there.
 *
 * Student code sees the ES5 globals (as in JS-Interpreter), the helpers of the API table, `print`
 * and `__block`, and nothing else: the compartment's other globals (`globalThis`, `Compartment`,
 * `Proxy`, `Promise`, ...) are removed, and `Function`, `eval`, `Date` and `Math.random` throw a
 * clear error (new code would escape the guards; clocks and randomness would break exact replay).
 * The compartment's global object is then hardened, so no call can leave anything for the next.
 *
 * Every global a function uses is bound to a local of the declaring closure: a free name looked
 * up through a compartment's global scope costs about 30 times more than a local.
 */
import type { InstrumentedFunction } from './ses-instrument';
import { ES5_GLOBALS, NATIVE_NAMES, RESERVED_PREFIX } from './ses-names';

/** Messages of the refused built-ins, worded as the reference engine words them. */
export const REFUSED = {
  random: 'Math.random is not available here: use a random input instead (a random source), so that every run can be replayed exactly.',
  date: 'Date is not available here: use the "tick" input to know the time, so that every run can be replayed exactly.',
  code: 'Making code from text (Function, eval) is not available here: write the code in the function itself.',
};

/** What the declaring closure receives from the host. */
export interface SesEnvironment {
  /** `print`, `__block` and every API helper, by name. */
  readonly natives: Readonly<Record<string, (...args: never[]) => unknown>>;
  /** Called by a guard when the budget is spent: throws the failure. */
  readonly over: () => never;
  /** Called first in every catch block: rethrows a pending failure. */
  readonly caught: (e: unknown) => void;
}

/** What the declaring closure returns: the functions and access to the step counter. */
export interface SesDeclared {
  readonly fns: readonly ((...args: unknown[]) => unknown)[];
  /** Sets the steps left (a negative number makes every guard fail at once). */
  readonly set: (steps: number) => void;
  readonly get: () => number;
}

function thrower(name: string, message: string): () => never {
  const f = function (): never {
    throw new Error(message);
  };
  Object.defineProperty(f, 'name', { value: name });
  return f;
}

let shared: { math: object; date: object; code: () => never } | null = null;

/** The replacements of Math, Date and Function, made once (after lockdown, they are hardened). */
function replacements(): { math: object; date: object; code: () => never } {
  if (shared) return shared;
  const math = Object.create(Object.prototype) as Record<PropertyKey, unknown>;
  for (const key of Reflect.ownKeys(Math)) if (key !== 'random') Object.defineProperty(math, key, Object.getOwnPropertyDescriptor(Math, key) as PropertyDescriptor);
  Object.defineProperty(math, 'random', { value: thrower('random', REFUSED.random), writable: false, enumerable: false, configurable: false });
  const date = thrower('Date', REFUSED.date);
  Object.defineProperty(date, 'now', { value: thrower('now', REFUSED.date) });
  shared = { math: harden(math), date: harden(date), code: harden(thrower('Function', REFUSED.code)) };
  return shared;
}

/** A new compartment holding only the ES5 globals, the refusals, and nothing that can be changed. */
export function sandboxCompartment(): Compartment {
  const { math, date, code } = replacements();
  const c = new Compartment({ __options__: true, name: 'layerbot' });
  const g = c.globalThis;
  const keep = new Set<PropertyKey>(ES5_GLOBALS);
  for (const key of Reflect.ownKeys(g)) {
    if (!keep.has(key) && Object.getOwnPropertyDescriptor(g, key)?.configurable) delete g[key];
  }
  Object.defineProperty(g, 'Math', { value: math });
  Object.defineProperty(g, 'Date', { value: date });
  Object.defineProperty(g, 'Function', { value: code });
  Object.defineProperty(g, 'eval', { value: code });
  harden(g);
  return c;
}

/** The source of the closure that declares every function, each in its own scope. */
export function declaringSource(fns: readonly InstrumentedFunction[]): string {
  const env = `${RESERVED_PREFIX}env`;
  const globals = ES5_GLOBALS.map((n) => `${n} = ${env}.g.${n}`).join(',\n  ');
  const natives = NATIVE_NAMES.map((n) => `${n} = ${env}.natives.${n}`).join(',\n  ');
  // Each function in its own scope: functions cannot see or replace each other (as in the reference).
  const declared = fns.map((f) => `(function () {\n${f.code}\n;return ${f.declared};\n})()`).join(',\n');
  const p = RESERVED_PREFIX;
  return `(function (${env}) {
'use strict';
var ${globals};
var ${natives};
var ${p}s = -1, ${p}o = ${env}.over, ${p}c = ${env}.caught, ${p}ev = ${env}.g.eval, ${p}u = ${env}.undeclared;
return {
fns: [
${declared}
],
set: function (n) { ${p}s = n; },
get: function () { return ${p}s; }
};
})`;
}

/** Reading a name declared nowhere: SES would give undefined, JS-Interpreter (and V8) a ReferenceError. */
function undeclared(name: string): never {
  throw new ReferenceError(`${name} is not defined`);
}

/** Declares the functions in the compartment and returns them with the step counter's access. */
export function declare(c: Compartment, source: string, env: SesEnvironment): SesDeclared {
  const g = c.globalThis as Record<string, unknown>;
  const globals: Record<string, unknown> = {};
  for (const n of ES5_GLOBALS) globals[n] = g[n];
  globals.eval = g.eval;
  const make = c.evaluate(source) as (env: unknown) => SesDeclared;
  return make(harden({ g: globals, natives: env.natives, over: env.over, caught: env.caught, undeclared }));
}
