/**
 * `layerbot grade PACK SUBMISSION...`: runs every challenge of the pack on each submission and
 * prints the verdicts (a table, `--json`, and `--csv FILE`). Each SUBMISSION is a submission file
 * (`*.submission.json`) or a single controller file, matched to a challenge by its file name.
 * Several submissions are graded in parallel on worker threads, one per core; a single one is
 * graded in-process. Exit codes: 0 graded (failing verdicts are results), 2 bad pack or usage.
 */
import { availableParallelism } from 'node:os';
import { performance } from 'node:perf_hooks';
import { generateBody } from '../../../blocks/generate';
import { formatProblems } from '../../core/formats';
import type { Pack, SubmissionVerdict } from '../../core/packs';
import { parsePack } from '../../core/packs';
import { createInterpreterSandbox } from '../../core/sandbox/interpreter';
import { readTextFile, writeFileAtomic } from '../files';
import { gradeOnWorkers } from '../grade-pool';
import type { GradedFile } from '../grade-report';
import { gradeCsv, gradeJson, gradeTable } from '../grade-report';
import { gradeFile } from '../grade-submission';
import { InputError } from '../load';

export interface GradeCommandOptions {
  /** Write one CSV row per submission and challenge to this file. */
  readonly csv?: string;
  /** Print JSON instead of the table. */
  readonly json?: boolean;
  /** Worker threads (default: one per core). 1 grades in-process. */
  readonly jobs?: number;
  /** Seed every random source (source i gets seed + i). */
  readonly seed?: number;
  /** The longest one submission may take, in seconds, before it is stopped (default 300). */
  readonly timeout?: number;
  /** Cap on the step budget of one function call (default 20,000,000). */
  readonly maxSteps?: number;
}

/** Grades `submissions` against the pack file; resolves to the exit code. */
export async function gradeCommand(
  packFile: string,
  submissions: readonly string[],
  opts: GradeCommandOptions,
  out: (s: string) => void,
  err: (s: string) => void,
): Promise<number> {
  let packText: string;
  try {
    packText = readTextFile(packFile);
  } catch (e) {
    throw new InputError(e instanceof Error ? e.message : String(e));
  }
  const parsed = parsePack(packText, packFile);
  if (!parsed.ok) throw new InputError(formatProblems(parsed.problems));
  const pack = parsed.value;
  if (submissions.length === 0) throw new InputError('layerbot grade: give at least one submission or controller file to grade.');

  const started = performance.now();
  const jobs = Math.max(1, Math.min(opts.jobs ?? availableParallelism(), submissions.length));
  const verdicts = jobs === 1 ? gradeInProcess(pack, submissions, opts) : await gradeOnWorkers(pack, submissions, {
    jobs,
    timeoutMs: (opts.timeout ?? 300) * 1000,
    init: { packText, packFile, ...(opts.seed !== undefined ? { seed: opts.seed } : {}), ...(opts.maxSteps !== undefined ? { maxStepBudget: opts.maxSteps } : {}) },
  });
  const seconds = (performance.now() - started) / 1000;
  const graded: GradedFile[] = submissions.map((file, i) => ({ file, verdict: verdicts[i] }));

  if (opts.csv) writeFileAtomic(opts.csv, gradeCsv(graded));
  if (opts.json) out(gradeJson(pack, graded));
  else out(`${gradeTable(pack, graded)}\n\nGraded ${graded.length} ${graded.length === 1 ? 'submission' : 'submissions'} in ${seconds.toFixed(1)} s (${jobs} ${jobs === 1 ? 'thread' : 'worker threads'}).`);
  const unreadable = graded.filter((g) => g.verdict.challenges.some((c) => c.reasons.some((r) => r.criterion === 'the submission can be read')));
  for (const g of unreadable) err(`${g.file}: could not be graded: ${g.verdict.challenges[0].reasons[0].detail}`);
  return 0;
}

function gradeInProcess(pack: Pack, files: readonly string[], opts: GradeCommandOptions): SubmissionVerdict[] {
  const options = {
    sandbox: createInterpreterSandbox,
    generateBody,
    ...(opts.seed !== undefined ? { seed: opts.seed } : {}),
    ...(opts.maxSteps !== undefined ? { maxStepBudget: opts.maxSteps } : {}),
  };
  return files.map((file) => gradeFile(pack, file, options));
}
