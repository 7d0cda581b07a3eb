/**
 * Challenge packs: reading packs and submissions (problems named by challenge and JSON path),
 * judging a controller against a challenge's criteria and locks, and grading submissions.
 * Like the rest of app/core, no I/O: callers pass text and sandboxes in.
 */
export type { Challenge, ChallengeVerdict, Criterion, CriterionKind, Lock, Pack, Reason, Submission, ToolboxCategory, Verdict } from './model';
export { DEFAULT_CHALLENGE_TICKS, TOOLBOX_CATEGORIES } from './model';
export { parsePack, PACK_SCHEMA } from './parse-pack';
export { parseSubmission, serializeSubmission, SUBMISSION_FORMAT, SUBMISSION_SCHEMA, SUBMISSION_VERSION } from './parse-submission';
export { packProblems } from './semantics';
export { blockTally, countBlocks, isLocked } from './blocks';
export { lockChanges, normalizeBlocks } from './locks';
export type { ChallengeRun, GradeOptions, SetupFailure } from './runs';
export { challengeWorlds, DEFAULT_MAX_STEP_BUDGET, runChallenge } from './runs';
export { judge, reachTicks, verdictSummary } from './criteria';
export type { SubmissionVerdict } from './grade';
export { gradeChallenge, gradeSubmission, unreadableSubmission } from './grade';
