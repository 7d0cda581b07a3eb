/**
 * Lock checking: a locked layer or function of the starter must come back unchanged in the
 * submission. Only what changes behaviour counts: block ids, positions on the canvas, collapsed
 * state and descriptions are ignored, and Blockly variable ids are replaced by variable names
 * (the app may renumber them when it loads a workspace).
 */
import type { ControllerSpec, FunctionSpec, LayerSpec } from '../controller/model';
import type { Lock } from './model';

type Obj = Record<string, unknown>;
const isObj = (v: unknown): v is Obj => typeof v === 'object' && v !== null && !Array.isArray(v);
const IGNORED_BLOCK_KEYS = new Set(['id', 'x', 'y', 'collapsed', 'deletable', 'movable', 'editable']);

/** Every change to the locked parts, one sentence each; empty when the locks hold. */
export function lockChanges(starter: ControllerSpec, submitted: ControllerSpec, locks: readonly Lock[]): string[] {
  const changes: string[] = [];
  for (const lock of locks) {
    const before = starter.layers.find((l) => l.name === lock.layer);
    if (!before) continue; // the pack reader rejects such locks
    const after = submitted.layers.find((l) => l.name === lock.layer);
    if (lock.function === undefined) {
      if (!after) changes.push(`the locked layer "${lock.layer}" was removed or renamed`);
      else {
        const what = layerChange(before, after);
        if (what) changes.push(`the locked layer "${lock.layer}" was changed: ${what}`);
      }
      continue;
    }
    const fnBefore = before.functions.find((f) => f.name === lock.function);
    if (!fnBefore) continue;
    const fnAfter = after?.functions.find((f) => f.name === lock.function);
    const where = `the locked function "${lock.function}" (layer "${lock.layer}")`;
    if (!fnAfter) {
      const moved = submitted.layers.find((l) => l.functions.some((f) => f.name === lock.function));
      changes.push(moved ? `${where} was moved to layer "${moved.name}"` : `${where} was removed or renamed`);
      continue;
    }
    const what = functionChange(fnBefore, fnAfter);
    if (what) changes.push(`${where} was changed: ${what}`);
  }
  return changes;
}

/** The first difference between two versions of a layer, in words, or null. */
function layerChange(a: LayerSpec, b: LayerSpec): string | null {
  const aVars = new Map(a.variables.map((v) => [v.name, v.value]));
  const bVars = new Map(b.variables.map((v) => [v.name, v.value]));
  for (const [name, value] of aVars) {
    if (!bVars.has(name)) return `its variable ${name} was removed`;
    if (canonical(bVars.get(name)) !== canonical(value)) return `its variable ${name} is ${JSON.stringify(bVars.get(name))}, not ${JSON.stringify(value)}`;
  }
  for (const name of bVars.keys()) if (!aVars.has(name)) return `a variable ${name} was added`;
  if (canonical(a.randomSources) !== canonical(b.randomSources)) return 'its random sources changed';
  const aNames = a.functions.map((f) => f.name);
  const bNames = b.functions.map((f) => f.name);
  for (const name of aNames) if (!bNames.includes(name)) return `its function "${name}" was removed or renamed`;
  for (const name of bNames) if (!aNames.includes(name)) return `a function "${name}" was added`;
  // Within a tick, ties in the dependency order keep the file's order: reordering can change results.
  if (aNames.join() !== bNames.join()) return `its functions were reordered (${bNames.join(', ')} instead of ${aNames.join(', ')})`;
  for (const fa of a.functions) {
    const what = functionChange(fa, b.functions.find((f) => f.name === fa.name)!);
    if (what) return `function "${fa.name}": ${what}`;
  }
  return null;
}

/** The first difference between two versions of a function, in words, or null. */
function functionChange(a: FunctionSpec, b: FunctionSpec): string | null {
  if (a.output !== b.output) return `it returns ${b.output} instead of ${a.output}`;
  if (canonical(a.inputs) !== canonical(b.inputs)) return 'its inputs (arcs) changed';
  if (a.body.kind !== b.body.kind) return `it was switched from ${a.body.kind} to ${b.body.kind}`;
  if (a.body.kind === 'text' && b.body.kind === 'text') return a.body.code === b.body.code ? null : 'its code changed';
  if (a.body.kind === 'blocks' && b.body.kind === 'blocks') return canonical(normalizeBlocks(a.body.blocks)) === canonical(normalizeBlocks(b.body.blocks)) ? null : 'its blocks changed';
  return null;
}

/** Blocks JSON without what does not change behaviour, variable ids replaced by names. */
export function normalizeBlocks(blocks: unknown): unknown {
  const names = new Map<string, string>();
  if (isObj(blocks) && Array.isArray(blocks.variables)) {
    for (const v of blocks.variables) if (isObj(v) && typeof v.id === 'string' && typeof v.name === 'string') names.set(v.id, v.name);
  }
  const walk = (v: unknown): unknown => {
    if (Array.isArray(v)) return v.map(walk);
    if (!isObj(v)) return v;
    // A variable field refers to its variable by id: `{"id": "..."}`.
    if (typeof v.id === 'string' && names.has(v.id) && typeof v.type !== 'string') return { variable: names.get(v.id) };
    const out: Obj = {};
    const isBlock = typeof v.type === 'string';
    for (const [k, x] of Object.entries(v)) if (!(isBlock && IGNORED_BLOCK_KEYS.has(k))) out[k] = walk(x);
    return out;
  };
  if (isObj(blocks) && Array.isArray(blocks.variables)) {
    return { ...(walk({ ...blocks, variables: undefined }) as Obj), variables: [...names.values()].sort() };
  }
  return walk(blocks);
}

/** JSON text with keys sorted, so equal values give equal text. */
function canonical(v: unknown): string {
  return JSON.stringify(v, (_k, x: unknown) =>
    isObj(x) ? Object.fromEntries(Object.keys(x).sort().map((k) => [k, x[k]])) : x,
  ) ?? 'undefined';
}
