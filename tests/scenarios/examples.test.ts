/**
 * Every example controller on every example world, run through the same Session as the app with
 * the reference engine (JS-Interpreter) and the blocks generated headless, each with its expected
 * outcome stated exactly: the ticks run, the crash tick, and the tick each plan step was reached
 * (null: not reached). Runs stop when the plan is done, the robot crashes or 2000 ticks pass.
 */
import { exampleSession } from '../support/examples';

jest.setTimeout(60_000);

interface Outcome {
  readonly ticks: number;
  readonly crashTick: number | null;
  readonly reached: readonly (number | null)[];
}

const WORLDS = ['office', 'trap', 'trap-new', 'corridor', 'field', 'maze'] as const;
type WorldName = (typeof WORLDS)[number];

const done = (...reached: number[]): Outcome => ({ ticks: reached[reached.length - 1], crashTick: null, reached });
const crash = (tick: number, steps = 1): Outcome => ({ ticks: tick, crashTick: tick, reached: new Array<null>(steps).fill(null) });

/** The basic controller's outcomes: the textbook robot (and basic-random, whose patience never runs out on these worlds). */
const BASIC: Record<WorldName, Outcome> = {
  office: done(127, 170, 216, 284),
  // The textbook trap: it follows the wall round and crashes into it.
  trap: crash(93),
  'trap-new': crash(100),
  // A checkpoint at every bend: steering straight at each works.
  corridor: done(38, 68, 109, 139, 177),
  field: done(30, 76, 110, 146, 182, 221, 253, 288),
  // Steering at the exit walks into a dead end: no goal in 2000 ticks.
  maze: { ticks: 2000, crashTick: null, reached: [null] },
};

const EXPECTED: Record<string, Record<WorldName, Outcome>> = {
  basic: BASIC,
  'basic-random': BASIC,
  'nearest-goal': {
    // o109 is reached first as planned, then storage; the nearest goal next is o103, not o109
    // again, so the plan's order breaks there and the run goes on to the tick limit.
    office: { ticks: 2000, crashTick: null, reached: [131, 174, null, null] },
    trap: crash(93),
    'trap-new': crash(100),
    // Each bend is the nearest goal in turn: the same run as basic.
    corridor: done(38, 68, 109, 139, 177),
    // The robot starts on the barn, the plan's last step: nearest first, it drops the barn at
    // once, then visits the others in plan order, and never goes back to the barn.
    field: { ticks: 2000, crashTick: null, reached: [30, 77, 111, 147, 183, 222, 254, null] },
    maze: { ticks: 2000, crashTick: null, reached: [null] },
  },
  'value-iteration': {
    office: done(120, 162, 209, 290),
    // Both traps: around the walls, no crash.
    trap: done(117),
    'trap-new': done(141),
    corridor: done(39, 71, 114, 144, 184),
    field: done(33, 91, 129, 166, 207, 250, 286, 323),
    maze: done(291),
  },
};

const cases = Object.entries(EXPECTED).flatMap(([controller, byWorld]) => WORLDS.map((world) => [controller, world, byWorld[world]] as const));

describe('every example controller on every example world', () => {
  test.each(cases)('%s on %s', (controller, world, expected) => {
    const session = exampleSession(controller, world);
    const summary = session.run(2000);
    session.dispose();
    expect(summary.error).toBeNull();
    expect({ ticks: summary.ticks, crashTick: summary.crashTick, reached: summary.goals.map((g) => g.reachedTick) }).toEqual(expected);
  });
});
