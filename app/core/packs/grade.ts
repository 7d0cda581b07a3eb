/**
 * Grading: each challenge of a pack run on a student's controller through the same Session the app
 * uses, judged by its criteria. Nothing a submission holds stops the grading of the rest: a
 * controller that is missing, invalid, failing or looping gets a verdict saying so.
 */
import type { ControllerSpec } from '../controller/model';
import { judge } from './criteria';
import type { Challenge, ChallengeVerdict, Pack, Submission } from './model';
import type { GradeOptions } from './runs';
import { runChallenge } from './runs';

/** One student's verdicts on every challenge of a pack. */
export interface SubmissionVerdict {
  /** Who: the submission's student, or the file it came from. */
  readonly student: string;
  /** One verdict per challenge of the pack, in pack order. */
  readonly challenges: readonly ChallengeVerdict[];
  /** Challenges passed. */
  readonly passed: number;
  /** Things worth knowing that are no criterion (work for challenges the pack does not have...). */
  readonly notes: readonly string[];
}

/** Runs and judges one challenge; `controller` undefined means the student did not attempt it. */
export function gradeChallenge(challenge: Challenge, controller: ControllerSpec | undefined, options: GradeOptions): ChallengeVerdict {
  const head = { challenge: challenge.id, title: challenge.title };
  if (!controller) return { ...head, passed: false, reasons: [{ criterion: 'submitted', passed: false, detail: 'no controller for this challenge' }] };
  let runs: ReturnType<typeof runChallenge>;
  try {
    runs = runChallenge(challenge, controller, options);
  } catch (e) {
    // Not the student's code (the sandbox turns its failures into values): still a verdict, not a crash.
    runs = { setupError: `grading failed: ${e instanceof Error ? e.message : String(e)}` };
  }
  return { ...head, ...judge(challenge, controller, runs) };
}

/** Grades every challenge of `pack` on `submission`. */
export function gradeSubmission(pack: Pack, submission: Submission, options: GradeOptions, who?: string): SubmissionVerdict {
  const challenges = pack.challenges.map((c) => gradeChallenge(c, submission.controllers[c.id], options));
  const ids = new Set(pack.challenges.map((c) => c.id));
  const extra = Object.keys(submission.controllers).filter((id) => !ids.has(id));
  const notes: string[] = [];
  if (submission.pack !== pack.title) notes.push(`the submission is for the pack "${submission.pack}", not "${pack.title}"`);
  if (extra.length) notes.push(`controllers for challenges this pack does not have were ignored: ${extra.join(', ')}`);
  return { student: submission.student ?? who ?? 'unknown', challenges, passed: challenges.filter((c) => c.passed).length, notes };
}

/** The verdicts for a submission that cannot be read at all: every challenge fails with the reason. */
export function unreadableSubmission(pack: Pack, student: string, problem: string): SubmissionVerdict {
  const challenges = pack.challenges.map(
    (c): ChallengeVerdict => ({ challenge: c.id, title: c.title, passed: false, reasons: [{ criterion: 'the submission can be read', passed: false, detail: problem }] }),
  );
  return { student, challenges, passed: 0, notes: [] };
}

