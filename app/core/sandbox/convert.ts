/**
 * Moves values between the host and one JS-Interpreter instance by direct tree conversion
 * (the library's nativeToPseudo/pseudoToNative are quadratic: ~300 ms on a 150x150x5 grid).
 *
 * Inputs become read-only pseudo objects, cached by native identity, so an unchanged value passed
 * every tick is converted once; each keeps a link to its native, so returning an input (or
 * passing it to a helper) costs nothing and keeps its identity.
 */
import Interpreter from 'js-interpreter';

type Obj = Interpreter.Object;
type Value = Interpreter.Value;
/** Read once: with bundlers' interop, `Interpreter.Object` may be a getter on every access. */
const PseudoObject = Interpreter.Object;

/** Limits on values crossing back to the host, so a result cannot exhaust the host's memory. */
export const VALUE_LIMITS = {
  /** Entries in one list (a sparse `a[1e9] = 1` is cheap to build inside, not outside). */
  maxListLength: 1_000_000,
  /** List entries and record fields in one converted value. */
  maxCells: 10_000_000,
  /** Nesting depth of one converted value (keeps the host's recursion shallow). */
  maxDepth: 1_000,
};

/**
 * Why a value cannot cross back to the host. `message` describes the value in words a student
 * understands ("it holds a function"); the caller says which value it is.
 */
export class ValueProblem extends Error {
  constructor(
    readonly kind: 'exception' | 'resources',
    message: string,
  ) {
    super(message);
    this.name = 'ValueProblem';
  }
}

/** A read-only pseudo object made from an input, with the native it was made from. */
interface InputObject extends Obj {
  layerbotNative: object;
}

/** Getter/setter tables of inputs: inputs never get accessors (writes to them are refused). */
const NO_ACCESSORS: Record<string, unknown> = Object.freeze(Object.create(null) as Record<string, unknown>);

/** Converts values for one interpreter. */
export class Converter {
  /**
   * Two generations of the native -> pseudo cache. A WeakMap alone would keep the pseudo copy of
   * every value the history holds alive as long as the history does (several times the memory of
   * the values themselves); rotating generations drops copies not used for a while, and plain
   * Maps are faster to fill than WeakMaps.
   */
  private recent = new Map<object, Obj>();
  private older = new Map<object, Obj>();

  constructor(private readonly interp: Interpreter) {}

  /** Starts a new cache generation: values unused for two generations are converted again. */
  rotate(): void {
    this.older = this.recent;
    this.recent = new Map();
  }

  /** Empties the cache. */
  clear(): void {
    this.recent = new Map();
    this.older = new Map();
  }

  /** True when `obj` was made from an input (and so is read-only). */
  isInput(obj: Obj): boolean {
    return (obj as Partial<InputObject>).layerbotNative !== undefined;
  }

  /** The native value a read-only pseudo input was made from. */
  nativeOf(obj: Obj): object | undefined {
    return (obj as Partial<InputObject>).layerbotNative;
  }

  /** A native, deeply frozen argument as a read-only pseudo value (cached by identity). */
  toInput(v: unknown): Value {
    return typeof v === 'object' && v !== null ? this.inputObject(v) : primitive(v);
  }

  /** A native value (a helper's result) as a fresh, mutable pseudo value; inputs stay shared. */
  toLocal(v: unknown): Value {
    return typeof v === 'object' && v !== null ? this.localObject(v) : primitive(v);
  }

  /**
   * A pseudo value as a native JSON-like value: inputs come back as the very native objects;
   * holes and `undefined` list entries become null and `undefined` fields are left out (as JSON
   * does). Throws a ValueProblem for functions, cycles, special objects and oversized values.
   */
  toNative(v: Value): unknown {
    if (!(v instanceof PseudoObject)) return v;
    const known = (v as Partial<InputObject>).layerbotNative;
    if (known !== undefined) return known;
    try {
      return toNativeTree(v);
    } catch (e) {
      if (e instanceof ValueProblem) throw e;
      if (e instanceof RangeError) throw new ValueProblem('resources', 'it is too large');
      // A getter defined by the student code: its placeholder throws when read natively.
      throw new ValueProblem('exception', 'it holds a getter or setter');
    }
  }

  private cached(v: object): Obj | undefined {
    const hit = this.recent.get(v);
    if (hit !== undefined) return hit;
    const old = this.older.get(v);
    if (old !== undefined) this.recent.set(v, old);
    return old;
  }

  private inputObject(v: object): Obj {
    const hit = this.cached(v);
    if (hit !== undefined) return hit;
    // Built by hand rather than with `new Interpreter.Object`: inputs share one empty accessor
    // table, which halves the allocations of a big grid.
    const p = Object.create(PseudoObject.prototype) as InputObject;
    p.getter = NO_ACCESSORS;
    p.setter = NO_ACCESSORS;
    p.properties = Object.create(null) as Record<string, Value>;
    this.fill(p, v, true);
    // Read-only: the sandbox's write guard refuses writes to objects carrying both marks. (The
    // storage is not frozen natively: on these dictionary objects that would double the cost.)
    p.preventExtensions = true;
    p.layerbotNative = v;
    // Only frozen values are cached: an unfrozen one could change under the cached copy.
    if (Object.isFrozen(v)) this.recent.set(v, p);
    return p;
  }

  private localObject(v: object): Obj {
    const hit = this.cached(v);
    if (hit !== undefined) return hit;
    const p = new PseudoObject(null);
    this.fill(p, v, false);
    return p;
  }

  private fill(p: Obj, v: object, input: boolean): void {
    const props = p.properties;
    const child = (x: unknown): Value => (typeof x !== 'object' || x === null ? primitive(x) : input ? this.inputObject(x) : this.localObject(x));
    if (Array.isArray(v)) {
      p.proto = this.interp.ARRAY_PROTO;
      p.class = 'Array';
      for (let i = 0; i < v.length; i++) props[i] = child(v[i]);
      // The same descriptor as the interpreter's own arrays: `length` is not enumerable.
      LENGTH.value = v.length;
      Object.defineProperty(props, 'length', LENGTH);
    } else {
      p.proto = this.interp.OBJECT_PROTO;
      for (const k of Object.keys(v)) props[k] = child((v as Record<string, unknown>)[k]);
    }
  }
}

const LENGTH: PropertyDescriptor = { value: 0, writable: true, enumerable: false, configurable: false };

function primitive(v: unknown): Value {
  if (v === null) return null;
  switch (typeof v) {
    case 'number':
    case 'string':
    case 'boolean':
    case 'undefined':
      return v;
    default:
      // A caller's mistake, not the student's: arguments must be JSON-like values.
      throw new TypeError(`A sandbox argument must be a JSON-like value, not a ${typeof v}.`);
  }
}

const IN_PROGRESS = Symbol('in progress');

function toNativeTree(root: Obj): unknown {
  // Shared sub-values are converted once: without the memo, `a = [a, a]` thirty times over would
  // make a billion copies.
  const memo = new Map<Obj, unknown>();
  let cells = 0;
  const count = (n: number): void => {
    cells += n;
    if (cells > VALUE_LIMITS.maxCells) throw new ValueProblem('resources', `it holds more than ${formatCount(VALUE_LIMITS.maxCells)} entries`);
  };
  const visit = (p: Value, depth: number): unknown => {
    if (!(p instanceof PseudoObject)) return p;
    const known = (p as Partial<InputObject>).layerbotNative ?? memo.get(p);
    if (known === IN_PROGRESS) throw new ValueProblem('exception', 'it contains itself');
    if (known !== undefined) return known;
    if (depth > VALUE_LIMITS.maxDepth) throw new ValueProblem('resources', `it is nested more than ${formatCount(VALUE_LIMITS.maxDepth)} levels deep`);
    memo.set(p, IN_PROGRESS);
    const props = p.properties;
    let out: unknown;
    switch (p.class) {
      case 'Array': {
        const n = props.length as number;
        if (n > VALUE_LIMITS.maxListLength) {
          throw new ValueProblem('resources', `it holds a list of ${formatCount(n)} entries (the limit is ${formatCount(VALUE_LIMITS.maxListLength)})`);
        }
        count(n);
        const a = new Array<unknown>(n);
        for (let i = 0; i < n; i++) {
          const x = props[i];
          a[i] = x === undefined ? null : visit(x, depth + 1);
        }
        out = a;
        break;
      }
      case 'Object': {
        // Boxed primitives, dates and regular expressions are objects holding native `data`.
        if (p.data !== null) {
          out = special(p.data);
          break;
        }
        const o: Record<string, unknown> = {};
        for (const k in props) {
          const x = props[k];
          count(1);
          if (x !== undefined) o[k] = visit(x, depth + 1);
        }
        out = o;
        break;
      }
      case 'Function':
        throw new ValueProblem('exception', 'it is or holds a function');
      default:
        throw new ValueProblem('exception', `it is or holds ${p.class === 'Error' ? 'an error object' : 'a special object'}`);
    }
    memo.set(p, out);
    return out;
  };
  return visit(root, 0);
}

/** A boxed primitive becomes its value; other objects with native data cannot be kept. */
function special(data: unknown): unknown {
  if (typeof data === 'number' || typeof data === 'string' || typeof data === 'boolean') return data;
  throw new ValueProblem('exception', `it is or holds ${data instanceof RegExp ? 'a regular expression' : data instanceof Date ? 'a date' : 'a special object'}`);
}

/** 1234567 -> "1,234,567" (no locale: messages must not depend on the machine). */
export function formatCount(n: number): string {
  return String(n).replace(/\B(?=(\d{3})+(?!\d))/g, ',');
}
