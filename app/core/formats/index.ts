/**
 * Layerbot's file formats: worlds (`*.world.json`) and controllers (`*.controller.json`).
 *
 * Readers never throw on bad input: they return every problem with the file, a JSON path and a
 * plain-words message. Writers give pretty, stable JSON (format and version first), so files
 * diff well in version control. Validation uses validators generated ahead of time from the JSON
 * Schemas (no run-time code generation, which the app's Content Security Policy forbids).
 * This module does no I/O: callers pass text in and get text out.
 */
import { kindOfFormat } from './envelope';
import type { FileKind } from './envelope';

export type { FileProblem, Result } from './types';
export { formatProblems } from './types';
export { parseWorld, serializeWorld, worldProblems, WORLD_SCHEMA } from './world';
export { parseController, serializeController, CONTROLLER_SCHEMA } from './controller';
export { SerializeError } from './pretty';
export { FORMATS, CURRENT_VERSION } from './envelope';
export type { FileKind } from './envelope';
export { parseJsonText } from './json';
export type { JsonDocument, TextPosition } from './json';

/**
 * What kind of Layerbot file the text is, by its `"format"` field, or null when it is not one.
 * Works on files too broken to parse, so the caller can still pick the right reader and let it
 * explain the problems.
 */
export function detectFormat(text: string): FileKind | null {
  try {
    const value: unknown = JSON.parse(text.replace(/^\uFEFF/, ''));
    if (typeof value === 'object' && value !== null && !Array.isArray(value)) {
      return kindOfFormat((value as Record<string, unknown>).format) ?? null;
    }
    return null;
  } catch {
    const m = /"format"\s*:\s*"(layerbot-[a-z]+)"/.exec(text);
    return m ? (kindOfFormat(m[1]) ?? null) : null;
  }
}
