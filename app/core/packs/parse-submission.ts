/**
 * Reading submissions (`*.submission.json`): one student's controllers for a pack, by challenge
 * id. Only the controllers' shape is checked here; whether they run, and pass, is the grader's
 * verdict, so a student's broken controller never stops the rest of their work being graded.
 */
import type { ControllerSpec } from '../controller/model';
import type { FileProblem, JsonDocument, Result } from '../formats';
import { parseJsonText } from '../formats';
import { childPath } from '../formats/paths';
import { prettyJson } from '../formats/pretty';
import { serializeController } from '../formats';
import type { SchemaValidator } from '../formats/validator';
import { describeFound, schemaProblems } from '../formats/validator';
import { deepFreeze } from '../values';
import validateSubmissionSchema from './generated/submission.validate';
import { inlineController } from './inline';
import type { Submission } from './model';
import submissionSchema from './submission.schema.json';

/** The submission file's `format` value (formats/envelope.ts knows worlds, controllers and packs). */
export const SUBMISSION_FORMAT = 'layerbot-submission';
export const SUBMISSION_VERSION = 1;

/** The submission file's JSON Schema. */
export const SUBMISSION_SCHEMA: object = submissionSchema;

/** Reads a submission. `fileName` only names the file in problems. */
export function parseSubmission(text: string, fileName: string): Result<Submission> {
  const json = parseJsonText(text, fileName);
  if (!json.ok) return json;
  const doc: JsonDocument = json.value;
  const envelope = envelopeProblem(doc.value);
  if (envelope) {
    const at = doc.positionOf(envelope.path);
    return { ok: false, problems: [{ file: fileName, ...envelope, ...(at ? { line: at.line, column: at.column } : {}) }] };
  }
  const problems: FileProblem[] = schemaProblems(validateSubmissionSchema as SchemaValidator, submissionSchema, doc, fileName);
  const raw = doc.value as Record<string, unknown>;
  const controllers: Record<string, ControllerSpec> = {};
  const rawControllers = raw.controllers;
  if (typeof rawControllers === 'object' && rawControllers !== null && !Array.isArray(rawControllers)) {
    for (const [id, value] of Object.entries(rawControllers)) {
      const parsed = inlineController(value, childPath('$.controllers', id), doc, fileName, false);
      if (parsed.ok) controllers[id] = parsed.value;
      else problems.push(...parsed.problems);
    }
  }
  if (problems.length) return { ok: false, problems };
  return {
    ok: true,
    value: deepFreeze({ pack: raw.pack as string, ...(typeof raw.student === 'string' ? { student: raw.student } : {}), controllers }),
  };
}

function envelopeProblem(value: unknown): { path: string; message: string } | null {
  if (typeof value !== 'object' || value === null || Array.isArray(value)) {
    return { path: '$', message: `expected a Layerbot submission: an object {"format": "${SUBMISSION_FORMAT}", "version": 1, ...}, found ${describeFound(value)}` };
  }
  const r = value as Record<string, unknown>;
  if (r.format === undefined) return { path: '$', message: `missing field "format": a submission file starts with "format": "${SUBMISSION_FORMAT}"` };
  if (r.format === 'layerbot-controller') {
    return { path: '$.format', message: 'this file is a single controller, not a submission; give it to the grader as a controller file (*.controller.json)' };
  }
  if (r.format !== SUBMISSION_FORMAT) return { path: '$.format', message: `expected "${SUBMISSION_FORMAT}", found ${describeFound(r.format)}` };
  if (r.version === undefined) return { path: '$', message: `missing field "version": expected "version": ${SUBMISSION_VERSION}` };
  if (typeof r.version === 'number' && Number.isInteger(r.version) && r.version > SUBMISSION_VERSION) {
    return { path: '$.version', message: `this submission was made by a newer Layerbot (format version ${r.version}; this Layerbot reads version ${SUBMISSION_VERSION}); update Layerbot to grade it` };
  }
  return null;
}

/** A submission as file text, as the app exports it: pretty JSON, controllers by challenge id. */
export function serializeSubmission(submission: Submission): string {
  const controllers: Record<string, unknown> = {};
  for (const [id, spec] of Object.entries(submission.controllers)) controllers[id] = JSON.parse(serializeController(spec)) as unknown;
  return prettyJson({
    format: SUBMISSION_FORMAT,
    version: SUBMISSION_VERSION,
    pack: submission.pack,
    ...(submission.student !== undefined ? { student: submission.student } : {}),
    controllers,
  });
}
