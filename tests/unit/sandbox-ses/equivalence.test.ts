/**
 * The fast engine (SES, in a worker thread) and the reference engine (JS-Interpreter) give the same
 * history, tick for tick: positions, headings, whiskers, crashes, every function's output, printed
 * lines and errors.
 */
import { runFastSession } from '../../../app/cli/fast-session';
import type { TickDigest } from '../../../app/cli/fast-protocol';
import { exampleController, exampleSession, exampleWorld } from '../../support/examples';

function referenceDigests(controller: string, world: string, maxTicks: number): TickDigest[] {
  const session = exampleSession(controller, world);
  session.run(maxTicks);
  const out = [...session.history.slice()].map((r) => ({
    tick: r.tick,
    x: r.world.robot.x,
    y: r.world.robot.y,
    heading: r.world.robot.heading,
    whisker: r.world.whisker,
    crashed: r.world.crash !== null,
    outputs: r.outputs,
    printed: r.printed,
    error: r.error,
  }));
  session.dispose();
  return out;
}

async function compare(controller: string, world: string, maxTicks: number): Promise<number> {
  const fast = await runFastSession(exampleWorld(world), exampleController(controller), { maxTicks, digests: true });
  expect(fast.stopped).toBeNull();
  const reference = referenceDigests(controller, world, maxTicks);
  // Structured cloning turns frozen values into plain ones: compare values, tick by tick.
  expect(fast.digests?.length).toBe(reference.length);
  fast.digests?.forEach((d, i) => expect([d.tick, d]).toEqual([i, JSON.parse(JSON.stringify(reference[i])) as TickDigest]));
  return reference.length - 1;
}

describe('the fast engine gives the reference engine\'s history', () => {
  test('basic controller, office world: every tick equal, every goal reached', async () => {
    const ticks = await compare('basic', 'office', 2000);
    expect(ticks).toBe(284);
  }, 20_000);

  test('basic controller, robot trap: every tick equal up to the crash', async () => {
    const ticks = await compare('basic', 'trap', 2000);
    expect(ticks).toBe(93);
  }, 20_000);

  // Value iteration is slow in the reference engine (seconds per replan): its first ticks here; the
  // whole matrix runs with LAYERBOT_FULL_EQUIVALENCE=1 (about a minute and a half).
  const full = process.env.LAYERBOT_FULL_EQUIVALENCE === '1';
  const controllers = ['basic', 'basic-random', 'nearest-goal', ...(full ? ['value-iteration'] : [])];
  const worlds = ['office', 'trap', 'trap-new', 'maze', 'corridor', 'field'];
  test.each(controllers.flatMap((c) => worlds.map((w) => [c, w])))('%s controller in the %s world', async (c, w) => {
    await compare(c, w, 600);
  }, 60_000);

  test('value-iteration controller in the robot trap: the first ticks', async () => {
    await compare('value-iteration', 'trap', 40);
  }, 20_000);
});
