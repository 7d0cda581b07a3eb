/** Grading submissions: in-core, and the `grade` command's table, CSV and JSON. */
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { gradeCommand } from '../../../app/cli/commands/grade';
import { gradeSubmission } from '../../../app/core/packs';
import { challenge, controller, options, pack, packJson, submission, submissionJson } from './fixtures';

jest.setTimeout(60_000);
const tmp = mkdtempSync(join(tmpdir(), 'layerbot-grade-'));
const file = (name: string, content: unknown) => {
  const p = join(tmp, name);
  writeFileSync(p, typeof content === 'string' ? content : JSON.stringify(content, null, 2));
  return p;
};
const second = challenge({ id: 'slow', title: 'Drive slowly', criteria: [{ kind: 'withinTicks', ticks: 20 }], locked: [] });

describe('gradeSubmission', () => {
  test('one verdict per challenge; missing work and stray work are said', () => {
    const v = gradeSubmission(pack([challenge(), second]), submission({ east: controller(), other: controller() }), options);
    expect(v.student).toBe('Ada');
    expect(v.passed).toBe(1);
    expect(v.challenges.map((c) => [c.challenge, c.passed])).toEqual([['east', true], ['slow', false]]);
    expect(v.challenges[1].reasons).toEqual([{ criterion: 'submitted', passed: false, detail: 'no controller for this challenge' }]);
    expect(v.notes).toEqual(['controllers for challenges this pack does not have were ignored: other']);
  });
});

describe('layerbot grade', () => {
  const packFile = file('tiny.pack.json', packJson([challenge(), second]));
  const good = file('ada.submission.json', submissionJson({ east: controller(), slow: controller() }));
  const looping = file('bob.submission.json', submissionJson({ east: { ...controller({ speed: 'while (true) {}' }), stepBudget: 1000 } }, 'Bob'));
  const broken = file('eve.submission.json', '{"format": "layerbot-submission", "version": 1,');
  const single = file('east.controller.json', controller());

  async function grade(files: string[], opts: object = {}) {
    const out: string[] = [];
    const err: string[] = [];
    const code = await gradeCommand(packFile, files, opts, (s) => out.push(s), (s) => err.push(s));
    return { code, out: out.join('\n'), err: err.join('\n') };
  }

  test('a table of verdicts, in-process for one submission', async () => {
    const r = await grade([good]);
    expect(r.code).toBe(0);
    expect(r.out).toContain('Ada (' + good + '): 2 of 2 passed');
    expect(r.out).toContain('  PASS  east  reached a at tick 8, b at tick 18; no crash in 18 ticks');
    expect(r.out).toContain('(1 thread)');
  });

  test('many submissions on worker threads; bad ones get verdicts and never stop the batch', async () => {
    const csv = join(tmp, 'grades.csv');
    const r = await grade([good, looping, broken, single], { json: true, csv, jobs: 2 });
    expect(r.code).toBe(0);
    const json = JSON.parse(r.out);
    const passed = json.submissions.map((s: { challenges: { passed: boolean }[] }) => s.challenges.map((c) => c.passed));
    expect(passed).toEqual([[true, true], [false, false], [false, false], [true, false]]);
    expect(json.submissions[1].challenges[0].reasons.find((x: { criterion: string }) => x.criterion === 'reach the plan (a, b) in order').detail).toBe(
      'a and b not reached (an error stopped the run at tick 1)',
    );
    expect(json.submissions[2].challenges[0].reasons[0]).toMatchObject({ criterion: 'the submission can be read', passed: false });
    expect(json.submissions[3].student).toBe('east');
    expect(r.err).toContain(`${broken}: could not be graded: ${broken}: $: not valid JSON`);
    const rows = readFileSync(csv, 'utf8').trim().split('\n');
    expect(rows[0]).toBe('file,student,challenge,passed,summary,reasons');
    expect(rows).toHaveLength(1 + 4 * 2);
    expect(rows[1]).toMatch(new RegExp(`^${good},Ada,east,true,`));
  });

  test('a bad pack is an input error naming the challenge and field', async () => {
    const bad = file('bad.pack.json', packJson([challenge({ criteria: [{ kind: 'reachGoals', goals: ['zebra'] }] })]));
    await expect(gradeCommand(bad, [good], {}, () => {}, () => {})).rejects.toThrow(
      `${bad}: $.challenges[0].criteria[0].goals[0]: challenge "east": no goal is named "zebra" in the challenge world; its goals are: a, b, c`,
    );
  });
});
