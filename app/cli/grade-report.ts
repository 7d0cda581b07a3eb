/** `layerbot grade` output: a table for people, CSV for spreadsheets, JSON for programs. */
import type { Pack, SubmissionVerdict } from '../core/packs';
import { verdictSummary } from '../core/packs';

/** One graded file: the file and its verdicts. */
export interface GradedFile {
  readonly file: string;
  readonly verdict: SubmissionVerdict;
}

/** The table: for each submission, one line per challenge with PASS/FAIL and what happened. */
export function gradeTable(pack: Pack, graded: readonly GradedFile[]): string {
  const width = Math.max(...pack.challenges.map((c) => c.id.length));
  const lines = [`${pack.title}: ${pack.challenges.length} challenges, ${graded.length} ${graded.length === 1 ? 'submission' : 'submissions'}`];
  for (const { file, verdict } of graded) {
    lines.push('', `${verdict.student} (${file}): ${verdict.passed} of ${verdict.challenges.length} passed`);
    for (const note of verdict.notes) lines.push(`  note: ${note}`);
    for (const c of verdict.challenges) lines.push(`  ${c.passed ? 'PASS' : 'FAIL'}  ${c.challenge.padEnd(width)}  ${verdictSummary(c)}`);
  }
  if (graded.length > 1) {
    lines.push('', 'Summary');
    const nameWidth = Math.max(7, ...graded.map((g) => g.verdict.student.length));
    lines.push(`  ${'student'.padEnd(nameWidth)}  passed  ${pack.challenges.map((c) => c.id).join(' ')}`);
    for (const { verdict } of graded) {
      const marks = verdict.challenges.map((c, i) => (c.passed ? 'pass' : 'FAIL').padEnd(pack.challenges[i].id.length)).join(' ');
      lines.push(`  ${verdict.student.padEnd(nameWidth)}  ${`${verdict.passed}/${verdict.challenges.length}`.padEnd(6)}  ${marks}`);
    }
  }
  return lines.join('\n');
}

/** CSV: one row per submission and challenge; `reasons` lists every criterion with PASS/FAIL. */
export function gradeCsv(graded: readonly GradedFile[]): string {
  const rows = [['file', 'student', 'challenge', 'passed', 'summary', 'reasons']];
  for (const { file, verdict } of graded) {
    for (const c of verdict.challenges) {
      const reasons = c.reasons.map((r) => `${r.passed ? 'PASS' : 'FAIL'} ${r.criterion}${r.world !== undefined ? ` [${r.world}]` : ''}: ${r.detail}`).join(' | ');
      rows.push([file, verdict.student, c.challenge, String(c.passed), verdictSummary(c), reasons]);
    }
  }
  return `${rows.map((r) => r.map(csvField).join(',')).join('\n')}\n`;
}

function csvField(s: string): string {
  return /[",\n\r]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s;
}

/** JSON for programs: every challenge verdict with `passed` and its reasons. */
export function gradeJson(pack: Pack, graded: readonly GradedFile[]): string {
  return JSON.stringify(
    {
      pack: pack.title,
      challenges: pack.challenges.map((c) => c.id),
      submissions: graded.map(({ file, verdict }) => ({
        file,
        student: verdict.student,
        passed: verdict.passed,
        total: verdict.challenges.length,
        notes: verdict.notes,
        challenges: verdict.challenges.map((c) => ({ challenge: c.challenge, title: c.title, passed: c.passed, summary: verdictSummary(c), reasons: c.reasons })),
      })),
    },
    null,
    2,
  );
}
