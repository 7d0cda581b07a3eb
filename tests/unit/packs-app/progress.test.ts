/** The student's progress per pack: statuses, work, hints, verdicts, storage and submissions. */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Pack, Verdict } from '../../../app/core/packs';
import { parsePack, parseSubmission, serializeSubmission } from '../../../app/core/packs';
import {
  emptyProgress,
  forgetWork,
  progressKey,
  progressOf,
  readProgress,
  recordVerdict,
  recordWork,
  revealHint,
  setCurrent,
  setStudent,
  submissionFileName,
  submissionOf,
  tally,
  workFor,
  writeProgress,
} from '../../../app/renderer/packs/progress';

const parsed = parsePack(readFileSync(join(__dirname, '../../../examples/packs/intro.pack.json'), 'utf8'), 'intro.pack.json');
if (!parsed.ok) throw new Error('the intro pack does not parse');
const pack: Pack = parsed.value;
const [steer, visit] = pack.challenges;
const changed = { ...steer.starter, name: 'my steering' };
const failing: Verdict = { passed: false, reasons: [{ criterion: 'no crash', world: 'One flag', passed: false, detail: 'crashed at tick 20: the wall at (0,0)-(1,1)' }] };
const passing: Verdict = { passed: true, reasons: [{ criterion: 'no crash', passed: true, detail: 'no crash in 35 ticks' }] };

test('a new pack: nothing started, keyed by its title', () => {
  const p = emptyProgress(pack.title);
  expect(progressKey(pack.title)).toBe('layerbot.pack-progress.v1:Layered control, step by step');
  expect(progressOf(p, 'steer-one')).toEqual({ status: 'not started', hints: 0 });
  expect(tally(pack, p)).toEqual({ passed: 0, attempted: 0, total: 8 });
});

test('work that differs from the starter is kept and counts as an attempt; the starter itself is not stored', () => {
  let p = recordWork(emptyProgress(pack.title), 'steer-one', steer.starter, steer.starter);
  expect(progressOf(p, 'steer-one')).toEqual({ status: 'not started', hints: 0 });
  p = recordWork(p, 'steer-one', changed, steer.starter);
  expect(progressOf(p, 'steer-one').status).toBe('attempted');
  expect(workFor(p, 'steer-one', steer.starter).name).toBe('my steering');
  expect(workFor(p, 'visit-plan', visit.starter)).toBe(visit.starter);
  p = forgetWork(p, 'steer-one');
  expect(workFor(p, 'steer-one', steer.starter)).toBe(steer.starter);
  expect(progressOf(p, 'steer-one').status).toBe('attempted');
});

test('the status follows the latest verdict; hints go up one at a time, to the last', () => {
  let p = recordVerdict(emptyProgress(pack.title), 'steer-one', failing, 412.6);
  expect(progressOf(p, 'steer-one').status).toBe('attempted');
  expect(progressOf(p, 'steer-one').verdict).toEqual({ ...failing, ms: 413 });
  p = recordVerdict(p, 'steer-one', passing);
  expect(progressOf(p, 'steer-one').status).toBe('passed');
  expect(tally(pack, p)).toEqual({ passed: 1, attempted: 0, total: 8 });
  for (let i = 0; i < 5; i++) p = revealHint(p, 'steer-one', 3);
  expect(progressOf(p, 'steer-one').hints).toBe(3);
});

test('progress survives storage; broken or foreign records give empty progress', () => {
  let p = recordWork(emptyProgress(pack.title), 'steer-one', changed, steer.starter);
  p = recordVerdict(p, 'steer-one', failing, 10);
  p = revealHint(setStudent(setCurrent(p, 'steer-one'), 'Ada'), 'steer-one', 3);
  const back = readProgress(writeProgress(p), pack.title);
  expect(back).toEqual(p);
  expect(readProgress(null, pack.title)).toEqual(emptyProgress(pack.title));
  expect(readProgress('{not json', pack.title)).toEqual(emptyProgress(pack.title));
  expect(readProgress(writeProgress(p), 'Another pack')).toEqual(emptyProgress('Another pack'));
  const odd = JSON.stringify({ version: 1, pack: pack.title, challenges: { x: { status: 'won', hints: -2, verdict: { passed: 'yes' } } } });
  expect(progressOf(readProgress(odd, pack.title), 'x')).toEqual({ status: 'not started', hints: 0 });
});

test('the submission holds the touched challenges, the student and the pack, and the grader reads it', () => {
  let p = recordWork(emptyProgress(pack.title), 'steer-one', changed, steer.starter);
  p = recordVerdict(p, 'visit-plan', failing);
  p = setStudent(p, '  Ada Lovelace ');
  const sub = submissionOf(pack, p);
  expect(sub.student).toBe('Ada Lovelace');
  expect(Object.keys(sub.controllers)).toEqual(['steer-one', 'visit-plan']);
  expect(sub.controllers['steer-one'].name).toBe('my steering');
  expect(sub.controllers['visit-plan']).toBe(visit.starter);
  expect(submissionFileName(pack, p)).toBe('ada-lovelace-layered-control-step-by-step.submission.json');
  const read = parseSubmission(serializeSubmission(sub), 'x.submission.json');
  expect(read.ok).toBe(true);
});
