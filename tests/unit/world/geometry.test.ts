import { crossingAlong, directionTo, normalizeAngle, normalizeHeading, segmentsIntersect } from '../../../app/core/world/geometry';

describe('segment intersection (the textbook rule)', () => {
  test('crossing segments intersect', () => {
    expect(segmentsIntersect([[0, 0], [10, 10]], [[0, 10], [10, 0]])).toBe(true);
  });
  test('end points count', () => {
    expect(segmentsIntersect([[0, 0], [10, 0]], [[10, 0], [10, 10]])).toBe(true);
    expect(segmentsIntersect([[0, 0], [5, 0]], [[5, -1], [5, 1]])).toBe(true);
  });
  test('parallel segments never intersect, even when they overlap', () => {
    expect(segmentsIntersect([[0, 0], [10, 0]], [[5, 0], [15, 0]])).toBe(false);
    expect(segmentsIntersect([[0, 0], [10, 0]], [[0, 1], [10, 1]])).toBe(false);
  });
  test('segments that would cross if longer do not', () => {
    expect(segmentsIntersect([[0, 0], [4, 4]], [[0, 10], [10, 0]])).toBe(false);
  });
  test('crossingAlong gives the position along the first segment', () => {
    expect(crossingAlong([[0, 0], [10, 0]], [[5, -1], [5, 1]])).toBeCloseTo(0.5);
  });
});

describe('angles', () => {
  test('headings are kept in [0, 360)', () => {
    expect(normalizeHeading(360)).toBe(0);
    expect(normalizeHeading(-18)).toBe(342);
    expect(normalizeHeading(725)).toBe(5);
  });
  test('relative angles are kept in (-180, 180]', () => {
    expect(normalizeAngle(-180)).toBe(180);
    expect(normalizeAngle(180)).toBe(180);
    expect(normalizeAngle(359)).toBe(-1);
    expect(normalizeAngle(181)).toBe(-179);
  });
  test('direction to a point', () => {
    expect(directionTo([0, 0], [0, 5])).toBeCloseTo(90);
    expect(directionTo([0, 0], [-1, -1])).toBeCloseTo(225);
  });
});
