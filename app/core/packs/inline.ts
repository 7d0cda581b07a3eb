/**
 * Reads the worlds and controllers a pack or submission holds inline, with the formats' own
 * readers, so their problems say exactly what a world or controller file's problems say, only
 * with the path inside the pack (`$.challenges[2].world.walls[0]`) and its line in the pack file.
 */
import type { ControllerSpec } from '../controller/model';
import { validateController } from '../controller/validate';
import { parseController, parseWorld } from '../formats';
import type { FileProblem, Result } from '../formats';
import type { JsonDocument } from '../formats';
import type { WorldSpec } from '../world/world';

/** Re-roots a problem found in an inline object at `at` in the enclosing document. */
function reroot(p: { path: string; message: string }, at: string, doc: JsonDocument, file: string): FileProblem {
  const path = at + p.path.slice(1);
  const pos = doc.positionOf(path) ?? doc.positionOf(at);
  return { file, path, message: p.message, ...(pos ? { line: pos.line, column: pos.column } : {}) };
}

/** The inline world at `at` (a JSON path of `doc`), or its problems. */
export function inlineWorld(value: unknown, at: string, doc: JsonDocument, file: string): Result<WorldSpec> {
  const parsed = parseWorld(JSON.stringify(value) ?? 'null', file);
  return parsed.ok ? parsed : { ok: false, problems: parsed.problems.map((p) => reroot(p, at, doc, file)) };
}

/**
 * The inline controller at `at`, or its problems. With `graph`, the controller must also make
 * sense as a graph (a pack's starters must run; a student's work is judged, not rejected).
 */
export function inlineController(value: unknown, at: string, doc: JsonDocument, file: string, graph: boolean): Result<ControllerSpec> {
  const parsed = parseController(JSON.stringify(value) ?? 'null', file);
  if (!parsed.ok) return { ok: false, problems: parsed.problems.map((p) => reroot(p, at, doc, file)) };
  const problems = graph ? validateController(parsed.value) : [];
  return problems.length ? { ok: false, problems: problems.map((p) => reroot(p, at, doc, file)) } : parsed;
}
