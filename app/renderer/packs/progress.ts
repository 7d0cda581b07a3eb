/**
 * A student's progress on one pack, as the app keeps it in local storage (one entry per pack,
 * keyed by the pack's title): per challenge, its status, the work (the controller as file text),
 * how many hints are shown and the last verdict. DOM-free: the tests run it in Node.
 */
import type { ControllerSpec } from '../../core/controller/model';
import { parseController, serializeController } from '../../core/formats';
import type { Pack, Reason, Submission, Verdict } from '../../core/packs/model';

export type ChallengeStatus = 'not started' | 'attempted' | 'passed';

export interface ChallengeProgress {
  readonly status: ChallengeStatus;
  /** The student's controller for this challenge, as controller file text (absent: the starter). */
  readonly work?: string;
  /** Hints revealed so far. */
  readonly hints: number;
  /** The latest verdict, with the time it took (ms). */
  readonly verdict?: Verdict & { readonly ms?: number };
}

export interface PackProgress {
  readonly version: 1;
  /** The pack's title (progress is kept per title). */
  readonly pack: string;
  /** The student's name, for submissions. */
  readonly student: string;
  /** The challenge open last. */
  readonly current?: string;
  readonly challenges: Readonly<Record<string, ChallengeProgress>>;
}

const KEY_PREFIX = 'layerbot.pack-progress.v1:';

/** The storage key of a pack's progress. */
export function progressKey(packTitle: string): string {
  return KEY_PREFIX + packTitle;
}

export function emptyProgress(packTitle: string): PackProgress {
  return { version: 1, pack: packTitle, student: '', challenges: {} };
}

const NOT_STARTED: ChallengeProgress = { status: 'not started', hints: 0 };

/** A challenge's progress (not started when there is none). */
export function progressOf(p: PackProgress, id: string): ChallengeProgress {
  return p.challenges[id] ?? NOT_STARTED;
}

function withChallenge(p: PackProgress, id: string, next: ChallengeProgress): PackProgress {
  return { ...p, challenges: { ...p.challenges, [id]: next } };
}

/**
 * Keeps the student's controller for a challenge. Work that equals the starter is not stored
 * (and does not count as an attempt); other work makes a not-started challenge "attempted".
 */
export function recordWork(p: PackProgress, id: string, controller: ControllerSpec | null, starter: ControllerSpec): PackProgress {
  const before = progressOf(p, id);
  const text = controller ? controllerText(controller) : null;
  const same = text === null || text === controllerText(starter);
  const status: ChallengeStatus = before.status === 'not started' && !same ? 'attempted' : before.status;
  const { work: _old, ...rest } = before;
  return withChallenge(p, id, same ? { ...rest, status } : { ...rest, status, work: text });
}

/** Records a check's verdict: the status follows the latest verdict. */
export function recordVerdict(p: PackProgress, id: string, verdict: Verdict, ms?: number): PackProgress {
  const before = progressOf(p, id);
  const kept: Verdict & { ms?: number } = { passed: verdict.passed, reasons: verdict.reasons.map(copyReason), ...(ms !== undefined ? { ms: Math.round(ms) } : {}) };
  return withChallenge(p, id, { ...before, status: verdict.passed ? 'passed' : 'attempted', verdict: kept });
}

/** Reveals the next hint (up to `total`). */
export function revealHint(p: PackProgress, id: string, total: number): PackProgress {
  const before = progressOf(p, id);
  return withChallenge(p, id, { ...before, hints: Math.min(total, before.hints + 1) });
}

/** Drops the work (back to the starter), keeping status and hints. */
export function forgetWork(p: PackProgress, id: string): PackProgress {
  const { work: _w, ...rest } = progressOf(p, id);
  return withChallenge(p, id, rest);
}

export function setCurrent(p: PackProgress, id: string): PackProgress {
  return { ...p, current: id };
}

export function setStudent(p: PackProgress, student: string): PackProgress {
  return { ...p, student };
}

/** The controller to open for a challenge: the saved work when it can be read, else the starter. */
export function workFor(p: PackProgress, id: string, starter: ControllerSpec): ControllerSpec {
  const work = progressOf(p, id).work;
  if (!work) return starter;
  const parsed = parseController(work, `${id}.controller.json`);
  return parsed.ok ? parsed.value : starter;
}

/** Counts per status, in pack order. */
export function tally(pack: Pack, p: PackProgress): { passed: number; attempted: number; total: number } {
  let passed = 0;
  let attempted = 0;
  for (const c of pack.challenges) {
    const s = progressOf(p, c.id).status;
    if (s === 'passed') passed++;
    else if (s === 'attempted') attempted++;
  }
  return { passed, attempted, total: pack.challenges.length };
}

/**
 * The student's submission: the work of every challenge they touched (attempted or passed),
 * the starter standing in for work that equals it.
 */
export function submissionOf(pack: Pack, p: PackProgress): Submission {
  const controllers: Record<string, ControllerSpec> = {};
  for (const c of pack.challenges) {
    if (progressOf(p, c.id).status === 'not started' && !progressOf(p, c.id).work) continue;
    controllers[c.id] = workFor(p, c.id, c.starter);
  }
  return { pack: pack.title, ...(p.student.trim() ? { student: p.student.trim() } : {}), controllers };
}

/** A file name for the submission: `<student>-<pack>.submission.json`. */
export function submissionFileName(pack: Pack, p: PackProgress): string {
  const slug = (s: string) => s.trim().toLowerCase().replace(/[^a-z0-9]+/g, '-').replace(/^-|-$/g, '');
  const parts = [slug(p.student), slug(pack.title)].filter((x) => x);
  return `${parts.join('-') || 'work'}.submission.json`;
}

/** Progress read back from storage; anything unreadable gives empty progress, never an exception. */
export function readProgress(text: string | null, packTitle: string): PackProgress {
  const empty = emptyProgress(packTitle);
  if (!text) return empty;
  let raw: unknown;
  try {
    raw = JSON.parse(text);
  } catch {
    return empty;
  }
  if (!isObj(raw) || raw.version !== 1 || raw.pack !== packTitle || !isObj(raw.challenges)) return empty;
  const challenges: Record<string, ChallengeProgress> = {};
  for (const [id, c] of Object.entries(raw.challenges)) {
    if (!isObj(c)) continue;
    const status: ChallengeStatus = c.status === 'passed' || c.status === 'attempted' ? c.status : 'not started';
    const hints = typeof c.hints === 'number' && Number.isInteger(c.hints) && c.hints >= 0 ? c.hints : 0;
    const verdict = readVerdict(c.verdict);
    challenges[id] = { status, hints, ...(typeof c.work === 'string' ? { work: c.work } : {}), ...(verdict ? { verdict } : {}) };
  }
  return {
    version: 1,
    pack: packTitle,
    student: typeof raw.student === 'string' ? raw.student : '',
    ...(typeof raw.current === 'string' ? { current: raw.current } : {}),
    challenges,
  };
}

export function writeProgress(p: PackProgress): string {
  return JSON.stringify(p);
}

function readVerdict(v: unknown): (Verdict & { ms?: number }) | undefined {
  if (!isObj(v) || typeof v.passed !== 'boolean' || !Array.isArray(v.reasons)) return undefined;
  const reasons = v.reasons.filter(
    (r): r is Reason => isObj(r) && typeof r.criterion === 'string' && typeof r.passed === 'boolean' && typeof r.detail === 'string' && (r.world === undefined || typeof r.world === 'string'),
  );
  return { passed: v.passed, reasons: reasons.map(copyReason), ...(typeof v.ms === 'number' ? { ms: v.ms } : {}) };
}

function copyReason(r: Reason): Reason {
  return { criterion: r.criterion, passed: r.passed, detail: r.detail, ...(r.world !== undefined ? { world: r.world } : {}) };
}

function controllerText(c: ControllerSpec): string {
  try {
    return serializeController(c);
  } catch {
    return JSON.stringify(c);
  }
}

function isObj(v: unknown): v is Record<string, unknown> {
  return typeof v === 'object' && v !== null && !Array.isArray(v);
}
