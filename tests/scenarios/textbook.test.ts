/**
 * The basic controller reproduces the textbook robot (Poole & Mackworth, chapter 2) tick for tick:
 * its trajectory is compared with traces written by tests/golden/textbook/textbook_robot.py, a
 * restatement of the textbook's own Python code. (SPEC T1-T8)
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { exampleSession, ROOT } from '../support/examples';
import { parseTrace, traceRows } from '../support/trace';

const reference = (name: string) => parseTrace(readFileSync(join(ROOT, 'tests', 'golden', 'textbook', `${name}.csv`), 'utf8'));

describe('the basic controller is the textbook robot', () => {
  test('office world: arrives after 127, 43, 46 and 68 ticks (284 in all)', () => {
    const session = exampleSession('basic', 'office');
    const summary = session.run(2000);
    expect(summary).toMatchObject({ ticks: 284, crashed: false, error: null });
    expect(summary.goals).toEqual([
      { name: 'o109', reachedTick: 127 },
      { name: 'storage', reachedTick: 170 },
      { name: 'o109', reachedTick: 216 },
      { name: 'o103', reachedTick: 284 },
    ]);
    expect(traceRows(session)).toEqual(reference('office'));
  });

  test('textbook trap: follows the wall and crashes at tick 93', () => {
    const session = exampleSession('basic', 'trap');
    const summary = session.run(2000);
    expect(summary).toMatchObject({ ticks: 93, crashed: true, crashTick: 93, error: null });
    expect(summary.goals).toEqual([{ name: expect.any(String), reachedTick: null }]);
    expect(traceRows(session)).toEqual(reference('trap'));
  });
});
