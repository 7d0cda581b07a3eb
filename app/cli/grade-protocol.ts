/** Messages between `layerbot grade` and its worker threads (grade-worker.ts). */
import type { SubmissionVerdict } from '../core/packs';

/** Parent -> worker, once: the pack (as text, parsed in the worker) and the run options. */
export interface GradeInit {
  readonly type: 'init';
  readonly packText: string;
  readonly packFile: string;
  readonly seed?: number;
  readonly maxStepBudget?: number;
}

/** Parent -> worker: grade one submission file. */
export interface GradeTask {
  readonly type: 'grade';
  readonly index: number;
  readonly file: string;
}

/** Worker -> parent. */
export type GradeReply =
  | { readonly type: 'ready' }
  | { readonly type: 'verdict'; readonly index: number; readonly verdict: SubmissionVerdict }
  | { readonly type: 'failed'; readonly message: string };
