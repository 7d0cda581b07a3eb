/**
 * The block generator the engine uses (`BodyGenerator`, app/core/controller/compile.ts): loads a
 * function's body JSON into a headless workspace and generates the body statements, ending with
 * `return ...;`, plus a debug variant with `__block('id');` before each block's statement.
 * Works in Node without a DOM. Results are cached by the body's JSON text and the names it sees.
 */
import * as Blockly from 'blockly/core';
import type { BodyGenerator, GeneratedBody } from '../app/core/controller/compile';
import type { FunctionSpec, LayerSpec } from '../app/core/controller/model';
import { FUNCTION_BLOCK } from './body/function';
import type { FunctionContext } from './context';
import { contextOf, setFunctionContext } from './context';
import { DEBUG_STATEMENT_PREFIX } from './generator';
import { layerbotGenerator, registerLayerbotBlocks } from './index';
import { BlocksError } from './types';

const PROCEDURE_DEFINITIONS = new Set(['procedures_defnoreturn', 'procedures_defreturn']);
const CACHE_LIMIT = 1000;
const cache = new Map<string, GeneratedBody>();

/** The workspace state a body JSON holds (a single block state is accepted too). */
export function bodyWorkspaceState(blocks: unknown): Record<string, unknown> {
  if (typeof blocks !== 'object' || blocks === null || Array.isArray(blocks)) {
    throw new BlocksError('The function\'s blocks are not in the expected form (a Blockly workspace saved as JSON).');
  }
  const state = blocks as Record<string, unknown>;
  if (typeof state.type === 'string') return { blocks: { languageVersion: 0, blocks: [state] } };
  return state;
}

/** Loads a body into a (headless or visible) workspace, with readable errors. */
export function loadBody(workspace: Blockly.Workspace, blocks: unknown, context: FunctionContext | null): void {
  registerLayerbotBlocks();
  const state = bodyWorkspaceState(blocks);
  try {
    Blockly.serialization.workspaces.load(state, workspace, { recordUndo: false });
  } catch (e) {
    const message = e instanceof Error ? e.message : String(e);
    const unknown = /Invalid block definition for type: (\S+)/.exec(message) ?? /block type[^"]*"?([\w-]+)"?/i.exec(message);
    throw new BlocksError(
      unknown
        ? `The function uses a block Layerbot does not know: "${unknown[1]}". It may come from a newer version or a typo in the file.`
        : `The function's blocks could not be loaded: ${message}`,
    );
  }
  if (context) setFunctionContext(workspace, context);
}

/** The body statements of the blocks in `workspace` (the function's root block and helpers). */
export function workspaceBody(workspace: Blockly.Workspace, context: FunctionContext, debug: boolean): string {
  const roots = workspace.getBlocksByType(FUNCTION_BLOCK, false);
  if (roots.length === 0) throw new BlocksError(`The function has no "function ${context.name}" block: its blocks must hang from that block.`);
  if (roots.length > 1) throw new BlocksError(`The function has ${roots.length} "function" blocks; keep one and move the blocks you need into it.`);
  const gen = layerbotGenerator();
  gen.useFunctionNames([...context.inputs, ...context.variables]);
  gen.STATEMENT_PREFIX = debug ? DEBUG_STATEMENT_PREFIX : null;
  try {
    gen.init(workspace);
    for (const block of workspace.getTopBlocks(true)) {
      if (PROCEDURE_DEFINITIONS.has(block.type)) gen.blockToCode(block);
    }
    const body = gen.blockToCode(roots[0]);
    return tidy(gen.finish(typeof body === 'string' ? body : ''));
  } catch (e) {
    if (e instanceof BlocksError) throw e;
    const message = e instanceof Error ? e.message : String(e);
    const unknown = /does not know how to generate code for block type "([^"]+)"/.exec(message);
    if (unknown) throw new BlocksError(`The block "${unknown[1]}" cannot be turned into code: it is not one of Layerbot's blocks.`);
    throw new BlocksError(`The blocks could not be turned into code: ${message}`);
  } finally {
    gen.STATEMENT_PREFIX = null;
    gen.isInitialized = false;
  }
}

/** Blockly separates definitions with blank lines; a function body reads better without them. */
function tidy(code: string): string {
  return `${code.replace(/\n{2,}/g, '\n').replace(/^\n+/, '').trimEnd()}\n`;
}

function generateUncached(fn: FunctionSpec, context: FunctionContext): GeneratedBody {
  if (fn.body.kind !== 'blocks') return { code: fn.body.code };
  const workspace = new Blockly.Workspace();
  try {
    loadBody(workspace, fn.body.blocks, context);
    return { code: workspaceBody(workspace, context, false), debugCode: workspaceBody(workspace, context, true) };
  } finally {
    workspace.dispose();
  }
}

/** Generates a blocks function's body (see `BodyGenerator`). */
export const generateBody: BodyGenerator = (fn: FunctionSpec, layer: LayerSpec): GeneratedBody => {
  const context = contextOf(fn, layer);
  const key = JSON.stringify([fn.body, context.inputs, context.variables, context.output]);
  const hit = cache.get(key);
  if (hit) return hit;
  const result = generateUncached(fn, context);
  if (cache.size >= CACHE_LIMIT) cache.delete(cache.keys().next().value as string);
  cache.set(key, result);
  return result;
};
