/**
 * The sample pack (examples/packs/intro.pack.json): every reference solution passes, and every
 * starter fails with a specific verdict, run through the same Session as the app.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Pack, Submission } from '../../app/core/packs';
import { gradeChallenge, parsePack, parseSubmission, verdictSummary } from '../../app/core/packs';
import { createInterpreterSandbox } from '../../app/core/sandbox/interpreter';
import { generateBody } from '../../blocks/generate';
import { ROOT } from '../support/examples';

jest.setTimeout(120_000);
const dir = join(ROOT, 'examples', 'packs');
const options = { sandbox: createInterpreterSandbox, generateBody };

function read<T>(parse: (t: string, f: string) => { ok: true; value: T } | { ok: false; problems: readonly { path: string; message: string }[] }, name: string): T {
  const parsed = parse(readFileSync(join(dir, name), 'utf8'), name);
  if (!parsed.ok) throw new Error(parsed.problems.map((p) => `${p.path}: ${p.message}`).join('\n'));
  return parsed.value;
}

const pack: Pack = read(parsePack, 'intro.pack.json');
const solution: Submission = read(parseSubmission, 'intro.solution.submission.json');

/** What each starter's verdict says: specific, so a student knows what to fix. */
const STARTER_VERDICTS: Record<string, string> = {
  'steer-one': 'on One flag: flag not reached (not within 300 ticks); on variant 1 ("One flag (left)"): flag not reached (not within 300 ticks); on variant 2 ("One flag (behind)"): flag not reached (not within 300 ticks); failed on One flag, variant 1 ("One flag (left)") and variant 2 ("One flag (behind)")',
  'visit-plan': 'reached o109 at tick 127; storage, o109 and o103 not reached (not within 600 ticks)',
  whisker: 'on Wall in the way: flag not reached (the robot crashed at tick 20); on Wall in the way: crashed at tick 20: the wall at (-12,20)-(10,20)',
  'whisker-sensor': 'on Wall in the way: flag not reached (the robot crashed at tick 20); on Wall in the way: crashed at tick 20: the wall at (-12,20)-(10,20)',
  'trap-escape': 'there is no layer "Value iteration" (the layers are "Top", "Middle" and "Bottom"); goal not reached (the robot crashed at tick 93); crashed at tick 93: the wall at (50,-21)-(50,31)',
  'cell-size': 'on Robot trap (new edition): goal not reached (an error stopped the run at tick 1)',
  'random-patience': 'layer "Top" has no function "patience"',
  'nearest-goal': 'the last goal, near, was reached at tick 88, after tick 80',
};

describe('the intro pack', () => {
  test('has about eight challenges, each with hints and a description', () => {
    expect(pack.challenges.length).toBeGreaterThanOrEqual(8);
    for (const c of pack.challenges) {
      expect(c.description.length).toBeGreaterThan(40);
      expect(c.hints.length).toBeGreaterThan(0);
    }
  });

  test.each(pack.challenges.map((c) => [c.id, c] as const))('the reference solution of %s passes', (_id, c) => {
    const v = gradeChallenge(c, solution.controllers[c.id], options);
    expect(v.reasons.filter((r) => !r.passed)).toEqual([]);
  });

  test.each(pack.challenges.map((c) => [c.id, c] as const))('the starter of %s fails with a specific verdict', (id, c) => {
    const v = gradeChallenge(c, c.starter, options);
    expect(v.passed).toBe(false);
    expect(verdictSummary(v)).toContain(STARTER_VERDICTS[id]);
  });
});
