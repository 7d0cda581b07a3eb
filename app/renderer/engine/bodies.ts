/**
 * Block code is generated on the page, not in the Worker: Blockly needs a DOM to load blocks,
 * and a Worker has none. The page generates every blocks function's body (generate.ts caches by
 * the body's JSON) and sends the text; the Worker's BodyGenerator only looks it up.
 */
import type { BodyGenerator, GeneratedBody } from '../../core/controller/compile';
import type { ControllerSpec } from '../../core/controller/model';

/** A generated body, or the student-readable reason it could not be generated. */
export type BodyResult = GeneratedBody | { readonly error: string };

/** Bodies keyed by `bodyKey(layer, function)`. */
export type BodyTable = Readonly<Record<string, BodyResult>>;

export const bodyKey = (layer: string, fn: string): string => `${layer}\u0000${fn}`;

/** Generates every blocks function's body with `generate`, keeping errors as values. */
export function generateBodies(controller: ControllerSpec, generate: BodyGenerator): BodyTable {
  const out: Record<string, BodyResult> = {};
  for (const layer of controller.layers) {
    for (const fn of layer.functions) {
      if (fn.body.kind !== 'blocks') continue;
      try {
        const g = generate(fn, layer);
        out[bodyKey(layer.name, fn.name)] = g.debugCode !== undefined ? { code: g.code, debugCode: g.debugCode } : { code: g.code };
      } catch (e) {
        out[bodyKey(layer.name, fn.name)] = { error: e instanceof Error ? e.message : String(e) };
      }
    }
  }
  return out;
}

/** The Worker's generator: the body the page sent, or its error. */
export function tableGenerator(table: BodyTable): BodyGenerator {
  return (fn, layer) => {
    const r = table[bodyKey(layer.name, fn.name)];
    if (!r) throw new Error('its blocks were not generated (the page sent no code for it).');
    if ('error' in r) throw new Error(r.error);
    return r;
  };
}
