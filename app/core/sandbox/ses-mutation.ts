/**
 * Tells a write to an input from other TypeErrors in the fast engine. Inputs are frozen, so strict
 * code writing to one gets V8's TypeError, which does not say which object it was: the property it
 * names is looked for among the inputs (first input first, as the reference engine names the first
 * input that holds the target). A refused write that matches no input hit a built-in.
 */
import type { SandboxFailureKind } from './types';

type Write = 'assign' | 'add' | 'delete';

// V8's messages for writes refused by frozen or non-extensible objects (strict mode), and SES's for
// the intrinsics' properties it turned into accessors (`of 'root.%ArrayPrototype%.push'`).
const PATTERNS: readonly [RegExp, Write][] = [
  [/^Cannot assign to read only property '(.+)' of (object )?'/, 'assign'],
  [/^Cannot add property (.+), object is not extensible$/, 'add'],
  [/^Cannot delete property '(.+)' of \[object /, 'delete'],
  [/^Cannot define property (.+), object is not extensible$/, 'add'],
  [/^Cannot redefine property: (.+)$/, 'assign'],
];

/** Objects searched per input at most: a huge grid is not walked to name the input. */
const SEARCH_LIMIT = 100_000;

/** The failure for a refused write, or null when the TypeError is something else. */
export function mutationMessage(message: string, params: readonly string[], args: readonly unknown[]): { kind: SandboxFailureKind; message: string } | null {
  for (const [pattern, write] of PATTERNS) {
    const m = pattern.exec(message);
    if (!m) continue;
    const property = m[1];
    for (let i = 0; i < args.length && i < params.length; i++) {
      if (holdsTarget(args[i], property, write)) {
        return {
          kind: 'mutation',
          message: `it tried to change its input "${params[i]}". Inputs cannot be changed: make a copy first (the "copy list" block) and change the copy.`,
        };
      }
    }
    return { kind: 'exception', message: `TypeError: Cannot change "${property}": built-in values and functions are read-only.` };
  }
  return null;
}

/** True when `root` is or holds a frozen object the refused write could have targeted. */
function holdsTarget(root: unknown, property: string, write: Write): boolean {
  const todo: unknown[] = [root];
  const seen = new Set<object>();
  while (todo.length > 0 && seen.size < SEARCH_LIMIT) {
    const v = todo.pop();
    if (typeof v !== 'object' || v === null || seen.has(v) || !Object.isFrozen(v)) continue;
    seen.add(v);
    if (couldBeTarget(v, property, write)) return true;
    for (const k of Object.keys(v)) todo.push((v as Record<string, unknown>)[k]);
  }
  return false;
}

function couldBeTarget(v: object, property: string, write: Write): boolean {
  const own = Object.prototype.hasOwnProperty.call(v, property);
  if (write !== 'add') return own;
  if (own) return false;
  // Adding an index to a list (push, or a write past its end) or a field to a record.
  return Array.isArray(v) ? /^\d+$/.test(property) : !/^\d+$/.test(property);
}
