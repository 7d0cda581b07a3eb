/** Numbers, points and walls as verdicts write them: short, exact where it matters. */
import type { Point, Segment } from '../world/geometry';

/** A coordinate: whole numbers as they are, others to two decimals. */
export function num(x: number): string {
  return Number.isInteger(x) ? String(x) : String(Math.round(x * 100) / 100);
}

export function point(p: Point): string {
  return `(${num(p[0])},${num(p[1])})`;
}

/** A wall as the textbook writes it: `(70,-5)-(70,25)`. */
export function wall(s: Segment): string {
  return `${point(s[0])}-${point(s[1])}`;
}

/** "a, b and c". */
export function list(items: readonly string[]): string {
  return items.length <= 1 ? (items[0] ?? '') : `${items.slice(0, -1).join(', ')} and ${items[items.length - 1]}`;
}
