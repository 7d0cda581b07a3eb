/**
 * The controller editor's logic that needs no DOM: unique names, copying a layer from another
 * controller, challenge locks, a function's code as the engine sees it, and switching a function
 * between blocks and text. The panes (blocks-pane.ts, code-pane.ts) call these; the unit tests
 * (tests/unit/editor) check them in Node.
 */
import type { BodyGenerator } from '../../core/controller/compile';
import { functionSource } from '../../core/controller/compile';
import type { ArcSource, ControllerSpec, FunctionBody, FunctionSpec, LayerSpec } from '../../core/controller/model';
import type { EditRestrictions } from '../panes/types';
import { emptyBody } from '../../../blocks/build';

/** Where a function lives: its layer's name and its own. */
export interface FunctionRef {
  readonly layer: string;
  readonly fn: string;
}

export function findFunction(spec: ControllerSpec | null, ref: FunctionRef | null): { layer: LayerSpec; fn: FunctionSpec } | null {
  if (!spec || !ref) return null;
  const layer = spec.layers.find((l) => l.name === ref.layer);
  const fn = layer?.functions.find((f) => f.name === ref.fn);
  return layer && fn ? { layer, fn } : null;
}

/** The layer that holds a function (function names are unique in a controller). */
export function layerOf(spec: ControllerSpec | null, fn: string): string | null {
  return spec?.layers.find((l) => l.functions.some((f) => f.name === fn))?.name ?? null;
}

/**
 * `base` if no name in `taken` has it, else `base` with the first free number: `steer2` for
 * names code uses (`spaced` false), `Middle 2` for layer names.
 */
export function uniqueName(base: string, taken: Iterable<string>, spaced = false): string {
  const names = new Set(taken);
  if (!names.has(base)) return base;
  const stem = base.replace(spaced ? / \d+$/ : /\d+$/, '') || base;
  for (let i = 2; ; i++) {
    const candidate = `${stem}${spaced ? ' ' : ''}${i}`;
    if (!names.has(candidate)) return candidate;
  }
}

export const functionNames = (spec: ControllerSpec): string[] => spec.layers.flatMap((l) => l.functions.map((f) => f.name));
export const randomNames = (spec: ControllerSpec): string[] => spec.layers.flatMap((l) => l.randomSources.map((r) => r.name));

/** What copying a layer into a controller did. */
export interface LayerCopy {
  /** The layer as added (renamed where its names clashed). */
  readonly layer: LayerSpec;
  /** The controller with the layer added at the bottom. */
  readonly spec: ControllerSpec;
  /** Names changed to avoid a clash, as "old → new". */
  readonly renamed: readonly string[];
  /** Functions the copied layer reads but this controller lacks. */
  readonly missing: readonly string[];
}

/**
 * Adds a copy of `layer` (from another controller) at the bottom of `spec`. The layer, its
 * functions and its random sources are renamed when their names are taken; arcs inside the
 * copied layer follow the renames. Arcs that read functions of other layers keep their names, so
 * the copy reads this controller's functions of that name (the missing ones are listed).
 */
export function copyLayerInto(spec: ControllerSpec, layer: LayerSpec): LayerCopy {
  const renamed: string[] = [];
  const layerName = uniqueName(layer.name, spec.layers.map((l) => l.name), true);
  if (layerName !== layer.name) renamed.push(`layer ${layer.name} → ${layerName}`);
  const fnTaken = new Set(functionNames(spec));
  const fnMap = new Map<string, string>();
  for (const fn of layer.functions) {
    const name = uniqueName(fn.name, fnTaken);
    fnTaken.add(name);
    fnMap.set(fn.name, name);
    if (name !== fn.name) renamed.push(`${fn.name} → ${name}`);
  }
  const rTaken = new Set(randomNames(spec));
  const rMap = new Map<string, string>();
  for (const r of layer.randomSources) {
    const name = uniqueName(r.name, rTaken);
    rTaken.add(name);
    rMap.set(r.name, name);
    if (name !== r.name) renamed.push(`${r.name} → ${name}`);
  }
  const source = (from: ArcSource): ArcSource => {
    if ((from.kind === 'function' || from.kind === 'previous') && fnMap.has(from.function)) return { ...from, function: fnMap.get(from.function)! };
    if (from.kind === 'random' && rMap.has(from.source)) return { ...from, source: rMap.get(from.source)! };
    return from;
  };
  const copy: LayerSpec = {
    ...layer,
    name: layerName,
    randomSources: layer.randomSources.map((r) => ({ ...r, name: rMap.get(r.name)! })),
    functions: layer.functions.map((fn) => ({ ...fn, name: fnMap.get(fn.name)!, inputs: fn.inputs.map((i) => ({ ...i, from: source(i.from) })) })),
  };
  const next: ControllerSpec = { ...spec, layers: [...spec.layers, copy] };
  const known = new Set(functionNames(next));
  const missing = new Set<string>();
  for (const fn of copy.functions) {
    for (const i of fn.inputs) if ((i.from.kind === 'function' || i.from.kind === 'previous') && !known.has(i.from.function)) missing.add(i.from.function);
  }
  return { layer: copy, spec: next, renamed, missing: [...missing] };
}

// ---------- Challenge locks ----------

export function isLayerLocked(r: EditRestrictions | null, layer: string): boolean {
  return !!r?.locked.some((l) => l.layer === layer && l.function === undefined);
}

export function isFunctionLocked(r: EditRestrictions | null, layer: string, fn: string): boolean {
  return !!r?.locked.some((l) => l.layer === layer && (l.function === undefined || l.function === fn));
}

const strip = (layer: LayerSpec): unknown => ({ ...layer, description: undefined });
const same = (a: unknown, b: unknown): boolean => JSON.stringify(a) === JSON.stringify(b);

/**
 * Why `after` breaks a lock that `before` respected (a locked layer or function changed or
 * disappeared), or null. Moving a locked layer up or down is allowed.
 */
export function lockViolation(before: ControllerSpec, after: ControllerSpec, r: EditRestrictions | null): string | null {
  if (!r) return null;
  for (const lock of r.locked) {
    const was = before.layers.find((l) => l.name === lock.layer);
    if (!was) continue;
    const now = after.layers.find((l) => l.name === lock.layer);
    if (lock.function === undefined) {
      if (!now || !same(strip(was), strip(now))) return `The layer “${lock.layer}” is locked in this challenge: you can look at it, not change it.`;
      continue;
    }
    const fnWas = was.functions.find((f) => f.name === lock.function);
    if (!fnWas) continue;
    const fnNow = now?.functions.find((f) => f.name === lock.function);
    if (!fnNow || !same(fnWas, fnNow)) return `The function “${lock.function}” (layer ${lock.layer}) is locked in this challenge: you can look at it, not change it.`;
  }
  return null;
}

// ---------- Code ----------

/** A function's code as the Code pane shows it. */
export type FunctionCode =
  /** Generated from blocks: the whole declaration the engine runs. */
  | { readonly kind: 'blocks'; readonly source: string }
  /** Text mode: the fixed header (declaration, strict mode, layer variables), the body, the closing brace. */
  | { readonly kind: 'text'; readonly header: string; readonly code: string; readonly footer: string }
  /** The blocks could not be turned into code. */
  | { readonly kind: 'error'; readonly message: string };

const BODY_MARK = '\u0000body\u0000';

/** The lines before and after a function's body in the declaration the engine runs. */
export function functionFrame(fn: FunctionSpec, layer: LayerSpec): { header: string; footer: string } {
  const full = functionSource(fn, layer, BODY_MARK);
  const at = full.indexOf(BODY_MARK);
  return { header: full.slice(0, at).trimEnd(), footer: full.slice(at + BODY_MARK.length).trim() };
}

export function functionCode(fn: FunctionSpec, layer: LayerSpec, generate: BodyGenerator): FunctionCode {
  if (fn.body.kind === 'text') return { kind: 'text', ...functionFrame(fn, layer), code: fn.body.code };
  try {
    return { kind: 'blocks', source: functionSource(fn, layer, generate(fn, layer).code) };
  } catch (e) {
    return { kind: 'error', message: e instanceof Error ? e.message : String(e) };
  }
}

/** The text body a blocks function becomes (its generated code), or why it cannot. */
export function textBodyOf(fn: FunctionSpec, layer: LayerSpec, generate: BodyGenerator): { body: FunctionBody } | { error: string } {
  if (fn.body.kind === 'text') return { body: fn.body };
  try {
    return { body: { kind: 'text', code: generate(fn, layer).code } };
  } catch (e) {
    return { error: e instanceof Error ? e.message : String(e) };
  }
}

/** The blocks body a text function becomes: a fresh function block (the text is not converted). */
export function blocksBodyFor(): FunctionBody {
  return { kind: 'blocks', blocks: emptyBody('b') };
}

/** The controller with one function's body replaced. */
export function withBody(spec: ControllerSpec, ref: FunctionRef, body: FunctionBody): ControllerSpec {
  return {
    ...spec,
    layers: spec.layers.map((l) => (l.name !== ref.layer ? l : { ...l, functions: l.functions.map((f) => (f.name === ref.fn ? { ...f, body } : f)) })),
  };
}

/** Arc source texts (`function:F`, `previous:F`, `random:R`) after renaming a function or a random source. */
export function renamedSource(source: string, kind: 'function' | 'random', from: string, to: string): string {
  const prefixes = kind === 'function' ? ['function:', 'previous:'] : ['random:'];
  for (const p of prefixes) if (source === p + from) return p + to;
  return source;
}
