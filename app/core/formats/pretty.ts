/**
 * JSON text for files people read and diff: two-space indentation, with any object or list that
 * fits on one line kept on one line (`[[20, 0], [30, 20]]`, `{ "name": "o109", "x": 100, "y": 10 }`),
 * so a world's walls and goals read one per line. Keys keep the order of the object given, so
 * writers decide the order (format and version first).
 */

import { childPath } from './paths';

const WIDTH = 100;

/** Thrown when a value cannot be written as JSON (a non-finite number, a function...). */
export class SerializeError extends Error {
  constructor(
    readonly path: string,
    message: string,
  ) {
    super(`${path}: ${message}`);
    this.name = 'SerializeError';
  }
}

/**
 * The value as pretty JSON text, ending with a newline. `expand(path)` may insist that the value
 * at a JSON path is laid out one item per line even when it would fit on one (a world's walls, a
 * controller's layers), so that files read and diff the same however small they are.
 */
export function prettyJson(value: unknown, expand: (path: string) => boolean = () => false): string {
  const write = (v: unknown, indent: string, path: string, used: number): string => writeValue(v, indent, path, used, expand);
  return `${write(value, '', '$', 0)}\n`;
}

function writeValue(value: unknown, indent: string, path: string, used: number, expand: (path: string) => boolean): string {
  if (value === null || typeof value === 'boolean' || typeof value === 'string') return JSON.stringify(value);
  if (typeof value === 'number') {
    if (!Number.isFinite(value)) throw new SerializeError(path, `${value} cannot be written in a JSON file; use a finite number`);
    return JSON.stringify(value);
  }
  if (typeof value !== 'object') throw new SerializeError(path, `a ${typeof value} cannot be written in a JSON file`);
  const entries: [string, unknown][] = Array.isArray(value)
    ? value.map((v, i) => [String(i), v])
    : Object.entries(value).filter(([, v]) => v !== undefined);
  const [open, close] = Array.isArray(value) ? ['[', ']'] : ['{', '}'];
  if (entries.length === 0) return `${open}${close}`;
  const inner = indent + '  ';
  const label = (k: string) => (Array.isArray(value) ? '' : `${JSON.stringify(k)}: `);
  const pathOf = (k: string) => childPath(path, Array.isArray(value) ? Number(k) : k);
  if (path !== '$' && !expand(path)) {
    const flat = oneLine(value, path, WIDTH - used);
    if (flat !== undefined) return flat;
  }
  const lines = entries.map(([k, v]) => `${inner}${label(k)}${writeValue(v, inner, pathOf(k), inner.length + label(k).length + 1, expand)}`);
  return `${open}\n${lines.join(',\n')}\n${indent}${close}`;
}

/** The value on one line, or undefined as soon as it is longer than `budget` (so big bodies stay cheap). */
function oneLine(value: unknown, path: string, budget: number): string | undefined {
  if (typeof value !== 'object' || value === null) {
    const text = writeValue(value, '', path, 0, () => false);
    return text.length <= budget ? text : undefined;
  }
  const entries: [string, unknown][] = Array.isArray(value) ? value.map((v, i) => [String(i), v]) : Object.entries(value).filter(([, v]) => v !== undefined);
  if (entries.length === 0) return Array.isArray(value) ? '[]' : '{}';
  const parts: string[] = [];
  // Brackets, braces with their padding spaces, and the ", " between items.
  let length = Array.isArray(value) ? 2 : 4;
  for (const [k, v] of entries) {
    const label = Array.isArray(value) ? '' : `${JSON.stringify(k)}: `;
    const text = oneLine(v, childPath(path, Array.isArray(value) ? Number(k) : k), budget - length - label.length);
    if (text === undefined) return undefined;
    length += label.length + text.length + (parts.length ? 2 : 0);
    if (length > budget) return undefined;
    parts.push(label + text);
  }
  return Array.isArray(value) ? `[${parts.join(', ')}]` : `{ ${parts.join(', ')} }`;
}
