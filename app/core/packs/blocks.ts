/**
 * Counting blocks in Blockly's serialization JSON without Blockly (app/core may not import it).
 * A block is an object with a `type` field reached as a top block, an input's `block` or a
 * `next` block. Shadow blocks (the grey defaults Blockly puts in empty inputs) are not counted:
 * students do not place them, and a real block in the same input hides them. The workspace's
 * variable list is not walked either: its entries carry a `type` field too, but are not blocks.
 */
import type { ControllerSpec, FunctionSpec, LayerSpec } from '../controller/model';
import type { Lock } from './model';

type Obj = Record<string, unknown>;
const isObj = (v: unknown): v is Obj => typeof v === 'object' && v !== null && !Array.isArray(v);

/** The number of blocks in a function body's blocks JSON (a workspace state or a single block). */
export function countBlocks(blocks: unknown): number {
  if (!isObj(blocks)) return 0;
  if (typeof blocks.type === 'string') return countBlock(blocks);
  const top = isObj(blocks.blocks) ? blocks.blocks.blocks : undefined;
  return Array.isArray(top) ? top.reduce((n: number, b) => n + countBlock(b), 0) : 0;
}

function countBlock(b: unknown): number {
  let n = 0;
  // `next` chains are walked in a loop, so a long sequence of statements cannot overflow the stack.
  for (let here: unknown = b; isObj(here) && typeof here.type === 'string'; here = isObj(here.next) ? here.next.block : undefined) {
    n++;
    if (isObj(here.inputs)) for (const input of Object.values(here.inputs)) if (isObj(input)) n += countBlock(input.block);
  }
  return n;
}

/** True when the function (in its layer) is locked, wholly or through its layer. */
export function isLocked(locks: readonly Lock[], layer: string, fn: string): boolean {
  return locks.some((l) => l.layer === layer && (l.function === undefined || l.function === fn));
}

/** Blocks per function, for the functions in scope; text-mode functions are listed apart. */
export function blockTally(
  spec: ControllerSpec,
  include: (fn: FunctionSpec, layer: LayerSpec) => boolean,
): { total: number; perFunction: { name: string; layer: string; blocks: number }[]; text: { name: string; layer: string }[] } {
  const perFunction: { name: string; layer: string; blocks: number }[] = [];
  const text: { name: string; layer: string }[] = [];
  for (const layer of spec.layers) {
    for (const fn of layer.functions) {
      if (!include(fn, layer)) continue;
      if (fn.body.kind === 'text') text.push({ name: fn.name, layer: layer.name });
      else perFunction.push({ name: fn.name, layer: layer.name, blocks: countBlocks(fn.body.blocks) });
    }
  }
  return { total: perFunction.reduce((n, f) => n + f.blocks, 0), perFunction, text };
}
