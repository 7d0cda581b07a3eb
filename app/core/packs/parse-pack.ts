/**
 * Reading challenge packs (`*.pack.json`): JSON text -> envelope (format, version) -> the pack's
 * JSON Schema -> every inline world and starter read by the formats' own readers -> checks that
 * need the whole pack (semantics.ts). Every problem names the file, the JSON path, and the
 * challenge it is in, so a teacher can find it; the reader never throws on bad input.
 */
import type { ControllerSpec } from '../controller/model';
import type { FileProblem, JsonDocument, Result } from '../formats';
import { parseJsonText } from '../formats';
import { openEnvelope } from '../formats/envelope';
import type { SchemaValidator } from '../formats/validator';
import { schemaProblems } from '../formats/validator';
import { deepFreeze } from '../values';
import type { WorldSpec } from '../world/world';
import validatePackSchema from './generated/pack.validate';
import { inlineController, inlineWorld } from './inline';
import type { Challenge, Criterion, Lock, Pack, ToolboxCategory } from './model';
import { DEFAULT_CHALLENGE_TICKS } from './model';
import packSchema from './pack.schema.json';
import { packProblems } from './semantics';

/** The pack file's JSON Schema (for editors, and for the app to offer). */
export const PACK_SCHEMA: object = packSchema;

type Raw = Record<string, unknown>;

/** Reads a challenge pack. `fileName` only names the file in problems. */
export function parsePack(text: string, fileName: string): Result<Pack> {
  const json = parseJsonText(text, fileName);
  if (!json.ok) return json;
  const envelope = openEnvelope(json.value, 'pack', fileName);
  if (!envelope.ok) return { ok: false, problems: envelope.problems };
  const doc: JsonDocument = { value: envelope.value, positionOf: json.value.positionOf };
  const problems: FileProblem[] = schemaProblems(validatePackSchema as SchemaValidator, packSchema, doc, fileName);
  const rawChallenges = Array.isArray(envelope.value.challenges) ? (envelope.value.challenges as unknown[]) : [];
  // Inline worlds and starters are read even when the pack's own shape has problems, so a teacher
  // sees every problem at once.
  const challenges = rawChallenges.map((raw, i) => readChallenge(raw, `$.challenges[${i}]`, doc, fileName, problems));
  if (!problems.length) {
    const pack: Pack = {
      title: envelope.value.title as string,
      author: envelope.value.author as string,
      description: envelope.value.description as string,
      challenges: challenges as Challenge[],
    };
    for (const p of packProblems(pack)) {
      const at = doc.positionOf(p.path);
      problems.push({ file: fileName, ...p, ...(at ? { line: at.line, column: at.column } : {}) });
    }
    if (!problems.length) return { ok: true, value: deepFreeze(pack) };
  }
  return { ok: false, problems: problems.map((p) => nameChallenge(p, rawChallenges)) };
}

/** Prefixes a problem inside a challenge with the challenge's id (or number), as teachers know it. */
function nameChallenge(p: FileProblem, raw: readonly unknown[]): FileProblem {
  const m = /^\$\.challenges\[(\d+)\]/.exec(p.path);
  if (!m) return p;
  const i = Number(m[1]);
  const id = (raw[i] as Raw | undefined)?.id;
  const name = typeof id === 'string' && id ? `challenge "${id}"` : `challenge ${i + 1}`;
  return { ...p, message: `${name}: ${p.message}` };
}

/** The challenge at `at`, or undefined when its parts have problems (added to `problems`). */
function readChallenge(raw: unknown, at: string, doc: JsonDocument, file: string, problems: FileProblem[]): Challenge | undefined {
  if (typeof raw !== 'object' || raw === null || Array.isArray(raw)) return undefined;
  const c = raw as Raw;
  const take = <T>(r: Result<T>): T | undefined => {
    if (r.ok) return r.value;
    problems.push(...r.problems);
    return undefined;
  };
  const world = 'world' in c ? take(inlineWorld(c.world, `${at}.world`, doc, file)) : undefined;
  const starter = 'starter' in c ? take(inlineController(c.starter, `${at}.starter`, doc, file, true)) : undefined;
  const rawCriteria = Array.isArray(c.criteria) ? (c.criteria as Raw[]) : [];
  const criteria = rawCriteria.map((cr, j) => readCriterion(cr, `${at}.criteria[${j}]`, (r) => take(r), doc, file));
  if (!world || !starter || criteria.some((x) => x === undefined)) return undefined;
  return {
    id: c.id as string,
    title: c.title as string,
    description: c.description as string,
    world,
    starter: starter as ControllerSpec,
    locked: ((c.locked as Lock[] | undefined) ?? []).map((l) => ({ layer: l.layer, ...(l.function !== undefined ? { function: l.function } : {}) })),
    ...(c.toolbox ? { toolbox: (c.toolbox as ToolboxCategory[]).slice() } : {}),
    criteria: criteria as Criterion[],
    hints: ((c.hints as string[] | undefined) ?? []).slice(),
    maxTicks: (c.maxTicks as number | undefined) ?? DEFAULT_CHALLENGE_TICKS,
  };
}

/** One criterion, with defaults filled in; variant worlds are read like the challenge's world. */
function readCriterion(cr: Raw, at: string, take: <T>(r: Result<T>) => T | undefined, doc: JsonDocument, file: string): Criterion | undefined {
  if (typeof cr !== 'object' || cr === null) return undefined;
  switch (cr.kind) {
    case 'reachGoals':
      return { kind: 'reachGoals', ...(Array.isArray(cr.goals) ? { goals: (cr.goals as string[]).slice() } : {}), order: cr.order === 'any' ? 'any' : 'plan' };
    case 'withinTicks':
      return { kind: 'withinTicks', ticks: cr.ticks as number };
    case 'noCrash':
    case 'noError':
      return { kind: cr.kind };
    case 'maxBlocks':
      return { kind: 'maxBlocks', blocks: cr.blocks as number, scope: cr.scope === 'all' ? 'all' : 'editable' };
    case 'hasFunction':
      return { kind: 'hasFunction', layer: cr.layer as string, function: cr.function as string };
    case 'variants': {
      const raw = Array.isArray(cr.worlds) ? (cr.worlds as unknown[]) : [];
      const worlds = raw.map((w, k) => take(inlineWorld(w, `${at}.worlds[${k}]`, doc, file)));
      return worlds.every((w) => w !== undefined) ? { kind: 'variants', worlds: worlds as WorldSpec[] } : undefined;
    }
    default:
      return undefined; // the schema has reported it
  }
}
