/** A verdict as the student reads it: headline, reasons grouped by world, ✓ and ✗. */
import type { Verdict } from '../../../app/core/packs';
import { headline, reasonLine, verdictGroups, verdictText } from '../../../app/renderer/packs/verdict';

const v: Verdict = {
  passed: false,
  reasons: [
    { criterion: 'locked parts unchanged', passed: true, detail: 'layer "Top" unchanged' },
    { criterion: 'reach the plan (o103) in order', world: 'Office', passed: true, detail: 'reached o103 at tick 140' },
    { criterion: 'no crash', world: 'Office', passed: false, detail: 'crashed at tick 171: the wall at (70,-5)-(70,25)' },
    { criterion: 'no crash', world: 'variant 1 ("Office (mirrored)")', passed: true, detail: 'no crash in 300 ticks' },
    { criterion: 'works on the challenge world and 1 variant', passed: false, detail: 'failed on Office' },
  ],
};

test('headline counts the failed checks, or says all hold', () => {
  expect(headline(v)).toBe('Not passed yet: 2 of 5 checks failed');
  expect(headline({ passed: true, reasons: v.reasons.slice(0, 1) })).toBe('Passed: the check holds');
  expect(headline({ passed: true, reasons: v.reasons.slice(0, 2) })).toBe('Passed: all 2 checks hold');
});

test('reasons about the controller come first, then each world in order', () => {
  const groups = verdictGroups(v);
  expect(groups.map((g) => g.world)).toEqual([null, 'Office', 'variant 1 ("Office (mirrored)")']);
  expect(groups[0].reasons.map((r) => r.criterion)).toEqual(['locked parts unchanged', 'works on the challenge world and 1 variant']);
});

test('each reason says what passed and what did not', () => {
  expect(reasonLine(v.reasons[2])).toBe('✗ no crash: crashed at tick 171: the wall at (70,-5)-(70,25)');
  expect(verdictText(v).split('\n')).toEqual([
    'Not passed yet: 2 of 5 checks failed',
    '✓ locked parts unchanged: layer "Top" unchanged',
    '✗ works on the challenge world and 1 variant: failed on Office',
    'On Office:',
    '  ✓ reach the plan (o103) in order: reached o103 at tick 140',
    '  ✗ no crash: crashed at tick 171: the wall at (70,-5)-(70,25)',
    'On variant 1 ("Office (mirrored)"):',
    '  ✓ no crash: no crash in 300 ticks',
  ]);
});
