/**
 * Values leaving the fast engine's compartment (results, helper arguments, printed values) are
 * checked and brought to the JSON-like form the reference engine gives them: holes and `undefined`
 * list entries become null, `undefined` fields are left out, functions, cycles and
 * special objects are refused with the reference engine's words, and the same size limits apply.
 * (A getter is read: it is student code, guarded; the reference engine refuses it instead.)
 * Objects already checked and frozen (inputs, earlier results) are remembered and never walked again.
 *
 * This runs on every call of every function, so it allocates nothing on its way through a value
 * that needs no fixing: the walk is a set of methods over the checker's own state, not closures.
 */
import { formatCount, VALUE_LIMITS, ValueProblem } from './convert';

const SPECIAL: Readonly<Record<string, string>> = { RegExp: 'a regular expression', Date: 'a date', Error: 'an error object' };

const { isArray } = Array;
const { freeze, isFrozen, getPrototypeOf, keys } = Object;
const ObjectPrototype = Object.prototype;

/** Checks values for one sandbox; remembers the frozen ones that passed. */
export class ValueChecker {
  /**
   * Frozen objects known to be JSON-like that hold other objects: checked once, shared by identity
   * afterwards. Lists of plain values (a grid's cell, a point) are frozen but not remembered:
   * walking one again costs less than a WeakSet entry (a 150 x 150 grid of cells would need
   * 22,500 entries per replan, and the collector pays for each).
   */
  private readonly clean: WeakSet<object>;
  /** True while a walk runs (a getter read during a walk may print, which walks again). */
  private busy = false;
  /** The objects on the path from the root to the one being walked (cycles, depth). */
  private readonly path: object[] = [];
  private cells = 0;
  private freezing = false;

  constructor(clean: WeakSet<object> = new WeakSet<object>()) {
    this.clean = clean;
  }

  /** A result: checked, fixed in place where needed (the object is the student's own) and deeply frozen. */
  result(v: unknown): unknown {
    return this.walk(v, true);
  }

  /** A helper's argument or a printed value: checked; a fixed copy when the value needs fixing. */
  argument(v: unknown): unknown {
    return this.walk(v, false);
  }

  private walk(root: unknown, freezing: boolean): unknown {
    if (typeof root !== 'object' || root === null) {
      if (typeof root === 'function') throw new ValueProblem('exception', 'it is or holds a function');
      return root;
    }
    if (this.clean.has(root)) return root;
    if (this.busy) return new ValueChecker(this.clean).walk(root, freezing);
    this.busy = true;
    this.freezing = freezing;
    this.cells = 0;
    try {
      return this.visit(root);
    } finally {
      // Empty after a walk that returns; a walk that throws leaves its path behind.
      if (this.path.length) this.path.length = 0;
      this.busy = false;
    }
  }

  private count(n: number): void {
    this.cells += n;
    if (this.cells > VALUE_LIMITS.maxCells) throw new ValueProblem('resources', `it holds more than ${formatCount(VALUE_LIMITS.maxCells)} entries`);
  }

  private visit(v: unknown): unknown {
    if (typeof v !== 'object' || v === null) {
      if (typeof v === 'function') throw new ValueProblem('exception', 'it is or holds a function');
      if (typeof v === 'symbol' || typeof v === 'bigint') throw new ValueProblem('exception', `it is or holds a ${typeof v}`);
      return v;
    }
    const array = isArray(v);
    if (array && v.length <= VALUE_LIMITS.maxListLength && plainLeaf(v)) {
      this.count(v.length);
      if (this.freezing) freeze(v);
      return v;
    }
    if (this.clean.has(v)) return v;
    const path = this.path;
    if (path.length > VALUE_LIMITS.maxDepth) {
      if (path.includes(v)) throw new ValueProblem('exception', 'it contains itself');
      throw new ValueProblem('resources', `it is nested more than ${formatCount(VALUE_LIMITS.maxDepth)} levels deep`);
    }
    path.push(v);
    const out = array ? this.visitArray(v as unknown[]) : this.visitRecord(v);
    path.pop();
    if (out === v && (this.freezing || isFrozen(v))) {
      freeze(v);
      this.clean.add(v);
    }
    return out;
  }

  private visitArray(a: unknown[]): unknown {
    const n = a.length;
    if (n > VALUE_LIMITS.maxListLength) tooLong(n);
    this.count(n);
    let copy: unknown[] | null = null;
    for (let i = 0; i < n; i++) {
      const x = a[i];
      const y = x === undefined ? null : this.visit(x);
      if (y !== x && copy === null) copy = this.freezing && !isFrozen(a) ? a : a.slice(0, i);
      if (copy !== null) copy[i] = y;
    }
    return copy ?? a;
  }

  private visitRecord(o: object): unknown {
    const proto = getPrototypeOf(o) as object | null;
    if (proto !== ObjectPrototype && proto !== null) return special(o);
    const record = o as Record<string, unknown>;
    const names = keys(record);
    this.count(names.length);
    let copy: Record<string, unknown> | null = null;
    for (let i = 0; i < names.length; i++) {
      const k = names[i];
      // A getter runs guarded student code; after the call, the exhausted budget stops it at once.
      const x = record[k];
      const y = x === undefined ? undefined : this.visit(x);
      if (y !== x && copy === null) copy = this.freezing && !isFrozen(o) ? record : { ...record };
      if (copy !== null) {
        if (y === undefined) delete copy[k];
        else copy[k] = y;
      }
    }
    return copy ?? o;
  }
}

/** True when every entry of `a` is a number, text, boolean or null (no holes, no undefined). */
function plainLeaf(a: readonly unknown[]): boolean {
  for (let i = 0; i < a.length; i++) {
    const x = a[i];
    const t = typeof x;
    if (t !== 'number' && t !== 'string' && t !== 'boolean' && x !== null) return false;
  }
  return true;
}

function tooLong(n: number): never {
  throw new ValueProblem('resources', `it holds a list of ${formatCount(n)} entries (the limit is ${formatCount(VALUE_LIMITS.maxListLength)})`);
}

/** Boxed primitives become their primitive (as in the reference); other objects are refused. */
function special(o: object): unknown {
  if (o instanceof Number || o instanceof String || o instanceof Boolean) return o.valueOf();
  const name = o instanceof RegExp ? 'RegExp' : o instanceof Date ? 'Date' : o instanceof Error ? 'Error' : '';
  throw new ValueProblem('exception', `it is or holds ${SPECIAL[name] ?? 'a special object'}`);
}
