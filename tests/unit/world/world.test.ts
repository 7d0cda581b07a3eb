import { editSpec, editState } from '../../../app/core/world/edits';
import type { WorldSpec } from '../../../app/core/world/world';
import { applyCommand, initialState, planComplete, whiskerSegment } from '../../../app/core/world/world';

const world: WorldSpec = {
  name: 'test',
  walls: [[[5, -10], [5, 10]]],
  goals: [
    { name: 'a', x: 0, y: 3 },
    { name: 'b', x: 0, y: 6 },
  ],
  plan: ['a', 'b', 'a'],
  robot: { x: 0, y: 0, heading: 90 },
};

describe('body physics', () => {
  test('a move is clamped to the max speed, and the heading normalised', () => {
    const s = applyCommand(initialState(world), { heading: 450, dx: 0, dy: 5 }, 1);
    expect(s.robot).toEqual({ x: 0, y: 1, heading: 90 });
  });

  test('unchanged parts are shared between states', () => {
    const s0 = initialState(world);
    const s1 = applyCommand(s0, { heading: 90, dx: 0, dy: 1 }, 1);
    expect(s1.walls).toBe(s0.walls);
    expect(s1.goals).toBe(s0.goals);
    expect(s1.robot).not.toBe(s0.robot);
  });

  test('crossing a wall is a crash: the robot stays, the tick and point are recorded, it moves no more', () => {
    let s = initialState({ ...world, robot: { x: 4.5, y: 0, heading: 0 } });
    s = applyCommand(s, { heading: 0, dx: 1, dy: 0 }, 7);
    expect(s.crash).toEqual({ tick: 7, point: [5, 0], wall: 0 });
    expect(s.robot.x).toBe(4.5);
    const after = applyCommand(s, { heading: 180, dx: -1, dy: 0 }, 8);
    expect(after).toBe(s);
  });

  test('plan steps are reached in order, one per tick, tick 0 counts', () => {
    let s = initialState({ ...world, robot: { x: 0, y: 2, heading: 90 } });
    expect(s.reached).toEqual([0, null, null]);
    s = applyCommand(s, { heading: 90, dx: 0, dy: 1 }, 1); // y=3: at a, but b is next
    expect(s.reached).toEqual([0, null, null]);
    s = applyCommand(s, { heading: 90, dx: 0, dy: 1 }, 2);
    expect(s.reached).toEqual([0, 2, null]); // y=4 is within 2 of b
    s = applyCommand(s, { heading: 90, dx: 0, dy: 1 }, 3);
    expect(s.reached).toEqual([0, 2, 3]); // y=5 is within 2 of a, the step after b
    expect(planComplete(s)).toBe(true);
  });

  test('the whisker points 30 degrees clockwise of the heading and senses walls', () => {
    const w = whiskerSegment({ x: 0, y: 0, heading: 90 }, { maxSpeed: 1, whiskerLength: 6, whiskerAngle: -30 });
    expect(w[1][0]).toBeCloseTo(3);
    expect(w[1][1]).toBeCloseTo(6 * Math.cos(Math.PI / 6));
    expect(initialState({ ...world, robot: { x: 1, y: 0, heading: 0 } }).whisker).toBe(true);
    expect(initialState(world).whisker).toBe(false);
  });
});

describe('world edits', () => {
  test('Create edits change the spec and keep names consistent', () => {
    let w = editSpec(world, { type: 'setGoal', name: 'a', goal: { name: 'home', x: 1, y: 1 } });
    expect(w.plan).toEqual(['home', 'b', 'home']);
    w = editSpec(w, { type: 'removeGoal', name: 'b' });
    expect(w.plan).toEqual(['home', 'home']);
    expect(() => editSpec(w, { type: 'setPlan', plan: ['nowhere'] })).toThrow('no goal by that name');
    expect(() => editSpec(w, { type: 'addGoal', goal: { name: 'home', x: 0, y: 0 } })).toThrow('already a goal');
  });

  test('edits while running sense the whisker again', () => {
    const s = editState(initialState(world), { type: 'moveRobot', x: 1, y: 0, heading: 0 });
    expect(s.whisker).toBe(true);
    expect(s.robot).toEqual({ x: 1, y: 0, heading: 0 });
  });
});
