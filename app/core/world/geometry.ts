/**
 * Plane geometry for the world: points, segments and angles in the textbook's conventions.
 * Coordinates are mathematical (x right, y up); angles are degrees counter-clockwise from +x.
 * Pure functions only: no state, no I/O.
 */

/** A point as `[x, y]`. */
export type Point = readonly [number, number];
/** A line segment between two end points. */
export type Segment = readonly [Point, Point];

const DEG = Math.PI / 180;

/** Degrees to radians. */
export function toRadians(degrees: number): number {
  return degrees * DEG;
}

/** Radians to degrees. */
export function toDegrees(radians: number): number {
  return radians / DEG;
}

/** An angle in degrees brought into [0, 360). */
export function normalizeHeading(degrees: number): number {
  const h = degrees % 360;
  const r = h < 0 ? h + 360 : h;
  return r === 360 ? 0 : r;
}

/** An angle in degrees brought into (-180, 180], as the textbook's steering compares directions. */
export function normalizeAngle(degrees: number): number {
  const a = ((((degrees + 540) % 360) + 360) % 360) - 180;
  return a === -180 ? 180 : a;
}

/** Euclidean distance between two points. */
export function distance(a: Point, b: Point): number {
  const dx = b[0] - a[0];
  const dy = b[1] - a[1];
  return Math.sqrt(dx * dx + dy * dy);
}

/**
 * Where segment `b` crosses segment `a`, as the position along `a` (0 at its start, 1 at its end),
 * or null when they do not intersect. This is the textbook's test (Poole & Mackworth, agentEnv.py):
 * parallel segments never intersect, and end points count.
 */
export function crossingAlong(a: Segment, b: Segment): number | null {
  // Indexing, not destructuring: this runs several times per wall per tick.
  const x0a = a[0][0];
  const y0a = a[0][1];
  const x0b = b[0][0];
  const y0b = b[0][1];
  const da = a[1][0] - x0a;
  const db = b[1][0] - x0b;
  const ea = a[1][1] - y0a;
  const eb = b[1][1] - y0b;
  const denom = db * ea - eb * da;
  if (denom === 0) return null;
  const cb = (da * (y0b - y0a) - ea * (x0b - x0a)) / denom;
  if (cb < 0 || cb > 1) return null;
  const ca = (db * (y0b - y0a) - eb * (x0b - x0a)) / denom;
  return ca >= 0 && ca <= 1 ? ca : null;
}

/** True when the two segments intersect, by the textbook's rule (see {@link crossingAlong}). */
export function segmentsIntersect(a: Segment, b: Segment): boolean {
  return crossingAlong(a, b) !== null;
}

/** The point at position `t` (0..1) along a segment. */
export function pointAlong(s: Segment, t: number): Point {
  return [s[0][0] + (s[1][0] - s[0][0]) * t, s[0][1] + (s[1][1] - s[0][1]) * t];
}

/** The segment of the given length from `from` in the direction `headingDegrees`. */
export function ray(from: Point, headingDegrees: number, length: number): Segment {
  const r = toRadians(headingDegrees);
  return [from, [from[0] + length * Math.cos(r), from[1] + length * Math.sin(r)]];
}

/** Direction from `from` to `to` in degrees, in [0, 360). */
export function directionTo(from: Point, to: Point): number {
  return normalizeHeading(toDegrees(Math.atan2(to[1] - from[1], to[0] - from[0])));
}
