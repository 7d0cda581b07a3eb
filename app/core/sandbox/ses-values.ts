/**
 * Values leaving the fast engine's compartment (results, helper arguments, printed values) are
 * checked and brought to the JSON-like form the reference engine gives them: holes and `undefined`
 * list entries become null, `undefined` fields are left out, functions, cycles and
 * special objects are refused with the reference engine's words, and the same size limits apply.
 * (A getter is read: it is student code, guarded; the reference engine refuses it instead.)
 * Objects already checked and frozen (inputs, earlier results) are remembered and never walked again.
 */
import { formatCount, VALUE_LIMITS, ValueProblem } from './convert';

const SPECIAL: Readonly<Record<string, string>> = { RegExp: 'a regular expression', Date: 'a date', Error: 'an error object' };

/** Checks values for one sandbox; remembers the frozen ones that passed. */
export class ValueChecker {
  /** Frozen objects known to be JSON-like: checked once, shared by identity afterwards. */
  private readonly clean = new WeakSet<object>();

  /** A result: checked, fixed in place where needed (the object is the student's own) and deeply frozen. */
  result(v: unknown): unknown {
    return this.walk(v, true);
  }

  /** A helper's argument or a printed value: checked; a fixed copy when the value needs fixing. */
  argument(v: unknown): unknown {
    return this.walk(v, false);
  }

  private walk(root: unknown, freeze: boolean): unknown {
    if (typeof root !== 'object' || root === null) {
      if (typeof root === 'function') throw new ValueProblem('exception', 'it is or holds a function');
      return root;
    }
    if (this.clean.has(root)) return root;
    // No memo of visited objects (a Map per call costs more than most results): frozen objects
    // that passed are remembered in `clean`, and a cycle shows up as a path deeper than the limit.
    const path: object[] = [];
    let cells = 0;
    const count = (n: number): void => {
      cells += n;
      if (cells > VALUE_LIMITS.maxCells) throw new ValueProblem('resources', `it holds more than ${formatCount(VALUE_LIMITS.maxCells)} entries`);
    };
    const visit = (v: unknown): unknown => {
      if (typeof v !== 'object' || v === null) {
        if (typeof v === 'function') throw new ValueProblem('exception', 'it is or holds a function');
        if (typeof v === 'symbol' || typeof v === 'bigint') throw new ValueProblem('exception', `it is or holds a ${typeof v}`);
        return v;
      }
      if (this.clean.has(v)) return v;
      if (path.length > VALUE_LIMITS.maxDepth) {
        if (path.includes(v)) throw new ValueProblem('exception', 'it contains itself');
        throw new ValueProblem('resources', `it is nested more than ${formatCount(VALUE_LIMITS.maxDepth)} levels deep`);
      }
      path.push(v);
      const out = Array.isArray(v) ? visitArray(v) : visitRecord(v);
      path.pop();
      if (out === v && (freeze || Object.isFrozen(v))) {
        Object.freeze(v);
        this.clean.add(v);
      }
      return out;
    };
    const visitArray = (a: unknown[]): unknown => {
      const n = a.length;
      if (n > VALUE_LIMITS.maxListLength) {
        throw new ValueProblem('resources', `it holds a list of ${formatCount(n)} entries (the limit is ${formatCount(VALUE_LIMITS.maxListLength)})`);
      }
      count(n);
      let copy: unknown[] | null = null;
      for (let i = 0; i < n; i++) {
        const x = a[i];
        const y = x === undefined ? null : visit(x);
        if (y !== x && copy === null) copy = freeze && !Object.isFrozen(a) ? a : a.slice(0, i);
        if (copy !== null) copy[i] = y;
      }
      return copy ?? a;
    };
    const visitRecord = (o: object): unknown => {
      const proto = Object.getPrototypeOf(o) as object | null;
      if (proto !== Object.prototype && proto !== null) return special(o);
      const record = o as Record<string, unknown>;
      const keys = Object.keys(record);
      count(keys.length);
      let copy: Record<string, unknown> | null = null;
      for (const k of keys) {
        // A getter runs guarded student code; after the call, the exhausted budget stops it at once.
        const x = record[k];
        const y = x === undefined ? undefined : visit(x);
        if (y !== x && copy === null) copy = freeze && !Object.isFrozen(o) ? record : { ...record };
        if (copy !== null) {
          if (y === undefined) delete copy[k];
          else copy[k] = y;
        }
      }
      return copy ?? o;
    };
    return visit(root);
  }
}

/** Boxed primitives become their primitive (as in the reference); other objects are refused. */
function special(o: object): unknown {
  if (o instanceof Number || o instanceof String || o instanceof Boolean) return o.valueOf();
  const name = o instanceof RegExp ? 'RegExp' : o instanceof Date ? 'Date' : o instanceof Error ? 'Error' : '';
  throw new ValueProblem('exception', `it is or holds ${SPECIAL[name] ?? 'a special object'}`);
}
