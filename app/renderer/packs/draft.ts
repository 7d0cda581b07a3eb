/**
 * The teacher's pack being written in the app: a plain model with the pack file's parts (title,
 * author, description, challenges with a world, a starter, locks, toolbox, criteria, hints), the
 * edits the pack editor makes, and the pack file text (`layerbot-pack` v1) that `parsePack`
 * checks before export. DOM-free.
 */
import type { ControllerSpec } from '../../core/controller/model';
import { parseController, parseWorld, serializeController, serializeWorld } from '../../core/formats';
import type { FileProblem } from '../../core/formats';
import type { Challenge, Criterion, Lock, Pack, ToolboxCategory } from '../../core/packs/model';
import { DEFAULT_CHALLENGE_TICKS, TOOLBOX_CATEGORIES } from '../../core/packs/model';
import { parsePack } from '../../core/packs/parse-pack';
import type { WorldSpec } from '../../core/world/world';

/** The criteria as the editor shows them: one switch (and its settings) per kind. */
export interface DraftCriteria {
  /** Reach goals: the plan (goals null) or the listed goals, in plan order or any order. */
  readonly reach: { readonly on: boolean; readonly goals: readonly string[] | null; readonly order: 'plan' | 'any' };
  readonly within: { readonly on: boolean; readonly ticks: number };
  readonly noCrash: boolean;
  readonly noError: boolean;
  readonly maxBlocks: { readonly on: boolean; readonly blocks: number; readonly scope: 'editable' | 'all' };
  /** Functions that must exist, by layer. */
  readonly functions: readonly { readonly layer: string; readonly function: string }[];
  /** Hidden variant worlds the controller must also pass on. */
  readonly variants: readonly WorldSpec[];
}

/** A challenge as the editor holds it: the toolbox and criteria in the form its controls edit. */
export interface DraftChallenge extends Omit<Challenge, 'toolbox' | 'criteria'> {
  /** The categories offered; null offers all of them. */
  readonly toolbox: readonly ToolboxCategory[] | null;
  readonly criteria: DraftCriteria;
}

export interface PackDraft {
  readonly title: string;
  readonly author: string;
  readonly description: string;
  readonly challenges: readonly DraftChallenge[];
}

export const PACK_SCHEMA_URL = 'https://layerbot.example/schemas/pack.schema.json';

export function emptyDraft(title = 'New pack', author = '', description = ''): PackDraft {
  return { title, author, description, challenges: [] };
}

export function defaultCriteria(world: WorldSpec): DraftCriteria {
  return {
    reach: { on: world.plan.length > 0 || world.goals.length > 0, goals: world.plan.length > 0 ? null : world.goals.map((g) => g.name), order: 'plan' },
    within: { on: false, ticks: 1000 },
    noCrash: true,
    noError: true,
    maxBlocks: { on: false, blocks: 100, scope: 'editable' },
    functions: [],
    variants: [],
  };
}

/** A challenge id from a title, unique among `taken`: "Visit a plan" -> "visit-a-plan". */
export function uniqueId(title: string, taken: readonly string[]): string {
  const base = title.toLowerCase().replace(/[^a-z0-9]+/g, '-').replace(/^-+|-+$/g, '') || 'challenge';
  let id = base;
  for (let i = 2; taken.includes(id); i++) id = `${base}-${i}`;
  return id;
}

/** Adds the world and controller as a new challenge at the end. */
export function addChallenge(d: PackDraft, world: WorldSpec, starter: ControllerSpec): PackDraft {
  const title = world.name || 'Challenge';
  const c: DraftChallenge = {
    id: uniqueId(title, d.challenges.map((x) => x.id)),
    title,
    description: world.description ?? '',
    world,
    starter,
    locked: [],
    toolbox: null,
    criteria: defaultCriteria(world),
    hints: [],
    maxTicks: DEFAULT_CHALLENGE_TICKS,
  };
  return { ...d, challenges: [...d.challenges, c] };
}

export function updateChallenge(d: PackDraft, index: number, change: (c: DraftChallenge) => DraftChallenge): PackDraft {
  return { ...d, challenges: d.challenges.map((c, i) => (i === index ? change(c) : c)) };
}

export function removeChallenge(d: PackDraft, index: number): PackDraft {
  return { ...d, challenges: d.challenges.filter((_, i) => i !== index) };
}

/** Moves item `index` by `delta` (-1 up, +1 down); out-of-range moves change nothing. */
export function move<T>(items: readonly T[], index: number, delta: number): T[] {
  const to = index + delta;
  const out = items.slice();
  if (index < 0 || index >= items.length || to < 0 || to >= items.length) return out;
  [out[index], out[to]] = [out[to], out[index]];
  return out;
}

export function moveChallenge(d: PackDraft, index: number, delta: number): PackDraft {
  return { ...d, challenges: move(d.challenges, index, delta) };
}

/** Locks or unlocks a whole layer; locking a layer drops the locks of its single functions. */
export function setLayerLock(c: DraftChallenge, layer: string, on: boolean): DraftChallenge {
  const others = c.locked.filter((l) => l.layer !== layer);
  return { ...c, locked: on ? [...others, { layer }] : others };
}

/** Locks or unlocks one function (meaningless while its whole layer is locked). */
export function setFunctionLock(c: DraftChallenge, layer: string, fn: string, on: boolean): DraftChallenge {
  const others = c.locked.filter((l) => !(l.layer === layer && l.function === fn));
  return { ...c, locked: on ? [...others, { layer, function: fn }] : others };
}

export function layerLocked(c: DraftChallenge, layer: string): boolean {
  return c.locked.some((l) => l.layer === layer && l.function === undefined);
}

export function functionLocked(c: DraftChallenge, layer: string, fn: string): boolean {
  return c.locked.some((l) => l.layer === layer && (l.function === undefined || l.function === fn));
}

/** Offers or withdraws a toolbox category; offering all of them again means "all" (null). */
export function setCategory(c: DraftChallenge, category: ToolboxCategory, on: boolean): DraftChallenge {
  const current = c.toolbox ?? TOOLBOX_CATEGORIES;
  const next = TOOLBOX_CATEGORIES.filter((k) => (k === category ? on : current.includes(k)));
  return { ...c, toolbox: next.length === TOOLBOX_CATEGORIES.length ? null : next };
}

export function setCriteria(c: DraftChallenge, change: (k: DraftCriteria) => DraftCriteria): DraftChallenge {
  return { ...c, criteria: change(c.criteria) };
}

/** The criteria in the pack file's form. */
export function criteriaOf(k: DraftCriteria): Criterion[] {
  const out: Criterion[] = [];
  if (k.reach.on) out.push({ kind: 'reachGoals', ...(k.reach.goals ? { goals: k.reach.goals.slice() } : {}), order: k.reach.order });
  if (k.within.on) out.push({ kind: 'withinTicks', ticks: k.within.ticks });
  if (k.noCrash) out.push({ kind: 'noCrash' });
  if (k.noError) out.push({ kind: 'noError' });
  if (k.maxBlocks.on) out.push({ kind: 'maxBlocks', blocks: k.maxBlocks.blocks, scope: k.maxBlocks.scope });
  for (const f of k.functions) out.push({ kind: 'hasFunction', layer: f.layer, function: f.function });
  if (k.variants.length) out.push({ kind: 'variants', worlds: k.variants.slice() });
  return out;
}

/** The editor's view of a pack's criteria (what the editor cannot show, e.g. two reach criteria, keeps the first). */
export function draftCriteria(criteria: readonly Criterion[], world: WorldSpec): DraftCriteria {
  const base = defaultCriteria(world);
  let k: DraftCriteria = { ...base, reach: { ...base.reach, on: false }, noCrash: false, noError: false };
  for (const c of criteria) {
    if (c.kind === 'reachGoals' && !k.reach.on) k = { ...k, reach: { on: true, goals: Array.isArray(c.goals) ? c.goals.slice() : null, order: c.order === 'any' ? 'any' : 'plan' } };
    if (c.kind === 'withinTicks') k = { ...k, within: { on: true, ticks: c.ticks } };
    if (c.kind === 'noCrash') k = { ...k, noCrash: true };
    if (c.kind === 'noError') k = { ...k, noError: true };
    if (c.kind === 'maxBlocks') k = { ...k, maxBlocks: { on: true, blocks: c.blocks, scope: c.scope } };
    if (c.kind === 'hasFunction') k = { ...k, functions: [...k.functions, { layer: c.layer, function: c.function }] };
    if (c.kind === 'variants') k = { ...k, variants: [...k.variants, ...c.worlds] };
  }
  return k;
}

/** A read pack as a draft, to edit it. */
export function draftOfPack(pack: Pack): PackDraft {
  return {
    title: pack.title,
    author: pack.author,
    description: pack.description,
    challenges: pack.challenges.map(
      (c: Challenge): DraftChallenge => ({
        id: c.id,
        title: c.title,
        description: c.description,
        world: c.world,
        starter: c.starter,
        locked: c.locked.slice(),
        toolbox: c.toolbox ? c.toolbox.slice() : null,
        criteria: draftCriteria(c.criteria, c.world),
        hints: c.hints.slice(),
        maxTicks: c.maxTicks,
      }),
    ),
  };
}

/** A world or controller as the object its file holds (format and version included). */
function worldObject(w: WorldSpec): unknown {
  return JSON.parse(serializeWorld(w)) as unknown;
}

function controllerObject(c: ControllerSpec): unknown {
  try {
    return JSON.parse(serializeController(c)) as unknown;
  } catch {
    return { format: 'layerbot-controller', version: 1, ...c };
  }
}

/** The pack file's JSON value. */
export function packValue(d: PackDraft): Record<string, unknown> {
  return {
    $schema: PACK_SCHEMA_URL,
    format: 'layerbot-pack',
    version: 1,
    title: d.title,
    author: d.author,
    description: d.description,
    challenges: d.challenges.map((c) => ({
      id: c.id,
      title: c.title,
      description: c.description,
      world: worldObject(c.world),
      starter: controllerObject(c.starter),
      locked: c.locked.map((l) => ({ layer: l.layer, ...(l.function !== undefined ? { function: l.function } : {}) })),
      ...(c.toolbox ? { toolbox: c.toolbox.slice() } : {}),
      criteria: criteriaOf(c.criteria).map((cr) => (cr.kind === 'variants' ? { kind: 'variants', worlds: cr.worlds.map(worldObject) } : cr)),
      hints: c.hints.slice(),
      maxTicks: c.maxTicks,
    })),
  };
}

/** The pack file text, as Export writes it. */
export function packText(d: PackDraft): string {
  return `${JSON.stringify(packValue(d), null, 2)}\n`;
}

/** The file name Export suggests. */
export function packFileName(d: PackDraft): string {
  const slug = d.title.trim().toLowerCase().replace(/[^a-z0-9]+/g, '-').replace(/^-|-$/g, '');
  return `${slug || 'pack'}.pack.json`;
}

/** Checks the draft as `parsePack` will read the exported file: the pack, or its problems. */
export function checkDraft(d: PackDraft): { ok: true; pack: Pack; text: string } | { ok: false; problems: readonly FileProblem[]; text: string } {
  const text = packText(d);
  const parsed = parsePack(text, packFileName(d));
  return parsed.ok ? { ok: true, pack: parsed.value, text } : { ok: false, problems: parsed.problems, text };
}

/**
 * A draft read back from storage, tolerant of what parsePack would refuse (a draft need not be
 * a valid pack yet): null only when the text is not a draft at all.
 */
export function readDraft(text: string | null): PackDraft | null {
  if (!text) return null;
  let raw: unknown;
  try {
    raw = JSON.parse(text);
  } catch {
    return null;
  }
  if (!isObj(raw) || raw.format !== 'layerbot-pack' || !Array.isArray(raw.challenges)) return null;
  const challenges: DraftChallenge[] = [];
  for (const c of raw.challenges) {
    if (!isObj(c)) continue;
    const world = parseWorld(JSON.stringify(c.world ?? null), 'draft.world.json');
    const starter = parseController(JSON.stringify(c.starter ?? null), 'draft.controller.json');
    if (!world.ok || !starter.ok) continue;
    const criteria: Criterion[] = [];
    for (const cr of Array.isArray(c.criteria) ? c.criteria : []) {
      if (!isObj(cr)) continue;
      if (cr.kind === 'variants') {
        const worlds = (Array.isArray(cr.worlds) ? cr.worlds : []).flatMap((w) => {
          const p = parseWorld(JSON.stringify(w), 'variant.world.json');
          return p.ok ? [p.value] : [];
        });
        criteria.push({ kind: 'variants', worlds });
      } else criteria.push(cr as unknown as Criterion);
    }
    challenges.push({
      id: typeof c.id === 'string' ? c.id : uniqueId('challenge', challenges.map((x) => x.id)),
      title: typeof c.title === 'string' ? c.title : '',
      description: typeof c.description === 'string' ? c.description : '',
      world: world.value,
      starter: starter.value,
      locked: (Array.isArray(c.locked) ? c.locked : []).filter((l): l is Lock => isObj(l) && typeof l.layer === 'string'),
      toolbox: Array.isArray(c.toolbox) ? (c.toolbox.filter((k) => (TOOLBOX_CATEGORIES as readonly unknown[]).includes(k)) as ToolboxCategory[]) : null,
      criteria: draftCriteria(criteria, world.value),
      hints: (Array.isArray(c.hints) ? c.hints : []).filter((h): h is string => typeof h === 'string'),
      maxTicks: typeof c.maxTicks === 'number' ? c.maxTicks : DEFAULT_CHALLENGE_TICKS,
    });
  }
  const str = (v: unknown) => (typeof v === 'string' ? v : '');
  return { title: str(raw.title), author: str(raw.author), description: str(raw.description), challenges };
}

function isObj(v: unknown): v is Record<string, unknown> {
  return typeof v === 'object' && v !== null && !Array.isArray(v);
}
