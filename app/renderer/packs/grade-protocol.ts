/** Messages between the page and the grading Worker (grade-worker.ts). */
import type { ControllerSpec } from '../../core/controller/model';
import type { Challenge, ChallengeVerdict } from '../../core/packs/model';
import type { BodyTable } from '../engine/bodies';

/** Page -> Worker: grade this controller on this challenge (block code generated on the page). */
export interface GradeRequest {
  readonly type: 'grade';
  readonly id: number;
  readonly challenge: Challenge;
  readonly controller: ControllerSpec;
  readonly bodies: BodyTable;
}

/** Worker -> page. */
export type GradeAnswer =
  | { readonly type: 'verdict'; readonly id: number; readonly verdict: ChallengeVerdict; readonly ms: number }
  | { readonly type: 'failed'; readonly id: number; readonly message: string };
