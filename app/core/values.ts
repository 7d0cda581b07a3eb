/**
 * Values that travel on arcs: plain JSON-like data, deeply frozen so that the history can share
 * them between ticks. The declared output types of functions and their checks live here.
 */

/** A JSON value. Arc values are JSON values (numbers may also be non-finite). */
export type JsonValue = null | boolean | number | string | readonly JsonValue[] | { readonly [key: string]: JsonValue };

/** The output types a function can declare. */
export const VALUE_TYPES = ['number', 'boolean', 'string', 'list', 'point', 'record', 'move', 'any'] as const;
export type ValueType = (typeof VALUE_TYPES)[number];

/** What each type means, in words a student reads in an error message. */
export const VALUE_TYPE_LABELS: Record<ValueType, string> = {
  number: 'a number',
  boolean: 'true or false',
  string: 'a text',
  list: 'a list',
  point: 'a point [x, y]',
  record: 'a record',
  move: 'a move {heading, dx, dy}',
  any: 'any value',
};

/** The body command: the new heading (degrees) and the change of position. */
export interface BodyCommand {
  readonly heading: number;
  readonly dx: number;
  readonly dy: number;
}

function isRecord(v: unknown): v is Record<string, unknown> {
  return typeof v === 'object' && v !== null && !Array.isArray(v);
}

/** Names the kind of a value the way a student would ("a list", "a number", "nothing"). */
export function describeValue(v: unknown): string {
  if (v === undefined) return 'nothing (the function returned no value)';
  if (v === null) return 'null';
  if (Array.isArray(v)) return v.length === 2 && typeof v[0] === 'number' && typeof v[1] === 'number' ? 'a point [x, y]' : 'a list';
  switch (typeof v) {
    case 'number':
      return Number.isNaN(v) ? 'NaN (not a number)' : 'a number';
    case 'boolean':
      return 'true or false';
    case 'string':
      return 'a text';
    case 'object':
      return 'a record';
    default:
      return `a ${typeof v}`;
  }
}

/** True when `v` fits the declared type. */
export function matchesType(v: unknown, type: ValueType): boolean {
  switch (type) {
    case 'any':
      return v !== undefined;
    case 'number':
      return typeof v === 'number' && !Number.isNaN(v);
    case 'boolean':
      return typeof v === 'boolean';
    case 'string':
      return typeof v === 'string';
    case 'list':
      return Array.isArray(v);
    case 'point':
      return Array.isArray(v) && v.length === 2 && typeof v[0] === 'number' && typeof v[1] === 'number';
    case 'record':
      return isRecord(v);
    case 'move':
      return isRecord(v) && isFiniteNumber(v.heading) && isFiniteNumber(v.dx) && isFiniteNumber(v.dy);
  }
}

function isFiniteNumber(v: unknown): v is number {
  return typeof v === 'number' && Number.isFinite(v);
}

/**
 * Freezes a value and everything inside it, in place, and returns it. Frozen values are never
 * copied again: the history and the sandboxes share them by identity.
 */
export function deepFreeze<T>(v: T): T {
  if (typeof v !== 'object' || v === null || Object.isFrozen(v)) return v;
  Object.freeze(v);
  for (const k of Object.keys(v)) deepFreeze((v as Record<string, unknown>)[k]);
  return v;
}

/**
 * Structural equality of JSON-like values. Identical objects are equal at once, so comparing a
 * value with itself, or with values that share their unchanged parts, costs little.
 */
export function sameValue(a: unknown, b: unknown): boolean {
  if (a === b) return true;
  if (typeof a === 'number' && typeof b === 'number') return Number.isNaN(a) && Number.isNaN(b);
  if (typeof a !== 'object' || typeof b !== 'object' || a === null || b === null) return false;
  if (Array.isArray(a)) {
    if (!Array.isArray(b) || a.length !== b.length) return false;
    // Equal entries (the usual case: grids of numbers and booleans) are told without a call.
    for (let i = 0; i < a.length; i++) {
      const x: unknown = a[i];
      const y: unknown = b[i];
      if (x !== y && !sameValue(x, y)) return false;
    }
    return true;
  }
  if (Array.isArray(b)) return false;
  const ra = a as Record<string, unknown>;
  const rb = b as Record<string, unknown>;
  let count = 0;
  for (const k in ra) {
    if (!Object.prototype.hasOwnProperty.call(rb, k) || !sameValue(ra[k], rb[k])) return false;
    count++;
  }
  for (const _k in rb) count--;
  return count === 0;
}

/** A short one-line rendering of a value for tables and messages. */
export function formatValue(v: unknown, maxLength = 80): string {
  let text: string;
  if (v === undefined) text = '—';
  else if (typeof v === 'number') text = formatNumber(v);
  else {
    try {
      text = JSON.stringify(v, (_k, x) => (typeof x === 'number' ? Number(formatNumber(x)) : x)) ?? String(v);
    } catch {
      text = String(v);
    }
  }
  return text.length > maxLength ? `${text.slice(0, maxLength - 1)}…` : text;
}

function formatNumber(n: number): string {
  if (!Number.isFinite(n)) return String(n);
  if (Number.isInteger(n)) return String(n);
  return String(Math.round(n * 1e4) / 1e4);
}
