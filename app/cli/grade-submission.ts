/**
 * Grading one submission file for `layerbot grade`, in a worker thread or in-process: reads the
 * file (a submission, or a single controller matched to a challenge), grades it, and always
 * returns a verdict, whatever the file holds.
 */
import { basename } from 'node:path';
import { parseController } from '../core/formats';
import { formatProblems } from '../core/formats';
import type { GradeOptions, Pack, Submission, SubmissionVerdict } from '../core/packs';
import { gradeSubmission, parseSubmission, unreadableSubmission } from '../core/packs';
import { readTextFile } from './files';

/** Grades the submission or controller file `file` against `pack`. Never throws. */
export function gradeFile(pack: Pack, file: string, options: GradeOptions): SubmissionVerdict {
  const who = basename(file).replace(/\.(submission|controller)\.json$/i, '').replace(/\.json$/i, '');
  try {
    const text = readTextFile(file);
    const submission = readSubmission(pack, text, file, who);
    if (typeof submission === 'string') return unreadableSubmission(pack, who, submission);
    return gradeSubmission(pack, submission, options, who);
  } catch (e) {
    return unreadableSubmission(pack, who, e instanceof Error ? e.message : String(e));
  }
}

/**
 * A submission from file text. A single controller file is taken as the work for one challenge:
 * the challenge whose id is the file's name (`visit-plan.controller.json`) or the controller's
 * name, or the pack's only challenge; anything else is ambiguous and said so.
 */
export function readSubmission(pack: Pack, text: string, file: string, who: string): Submission | string {
  if (topLevelFormat(text) !== 'layerbot-controller') {
    const parsed = parseSubmission(text, file);
    return parsed.ok ? parsed.value : formatProblems(parsed.problems);
  }
  const parsed = parseController(text, file);
  if (!parsed.ok) return formatProblems(parsed.problems);
  const spec = parsed.value;
  const challenge =
    pack.challenges.find((c) => c.id === who || c.id === spec.name) ?? (pack.challenges.length === 1 ? pack.challenges[0] : undefined);
  if (!challenge) {
    return (
      `${file}: cannot tell which challenge this controller is for; name the file after the challenge ` +
      `(${pack.challenges.map((c) => `${c.id}.controller.json`).join(', ')}) or hand in a submission file`
    );
  }
  return { pack: pack.title, student: who, controllers: { [challenge.id]: spec } };
}

/** The `format` field of the text's top-level object, if it is JSON at all. */
function topLevelFormat(text: string): unknown {
  try {
    const value: unknown = JSON.parse(text.replace(/^\uFEFF/, ''));
    return typeof value === 'object' && value !== null ? (value as Record<string, unknown>).format : undefined;
  } catch {
    return undefined;
  }
}
