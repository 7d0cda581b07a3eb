/**
 * Turns a controller's functions into sandbox-ready function declarations. The body of a blocks
 * function comes from a generator (blocks/ provides it; the engine knows nothing of Blockly); a
 * text-mode body is used as written. Layer variables are declared afresh in every call, so a
 * function that assigns one changes nothing for the next tick: functions stay pure.
 */
import type { CompiledFunction } from '../sandbox/types';
import { functionErrorMessage } from '../sandbox/types';
import type { ControllerSpec, FunctionSpec, LayerSpec } from './model';
import { allFunctions } from './model';

/** The statements of a function body, ending with its `return`. */
export interface GeneratedBody {
  readonly code: string;
  /** The same statements with `__block("id");` before each block, for stepping and attribution. */
  readonly debugCode?: string;
}

/** Generates the body of a blocks function. Throws an Error with a student-readable message. */
export type BodyGenerator = (fn: FunctionSpec, layer: LayerSpec) => GeneratedBody;

/** Raised when a function's body cannot be generated (e.g. no block generator is available). */
export class BodyError extends Error {
  constructor(
    readonly functionName: string,
    readonly layerName: string,
    detail: string,
  ) {
    super(functionErrorMessage(functionName, layerName, detail));
    this.name = 'BodyError';
  }
}

/** The statements a function body starts with: strict mode and the layer's variables. */
export function preamble(layer: LayerSpec): string {
  const vars = layer.variables.map((v) => `${v.name} = ${JSON.stringify(v.value)}`);
  return `'use strict';\n${vars.length ? `var ${vars.join(', ')};\n` : ''}`;
}

/** Wraps body statements into the full declaration the sandbox runs. */
export function functionSource(fn: FunctionSpec, layer: LayerSpec, body: string): string {
  const params = fn.inputs.map((i) => i.name).join(', ');
  return `function ${fn.name}(${params}) {\n${preamble(layer)}${body.trimEnd()}\n}`;
}

/** The generated (or written) body of one function. */
export function bodyOf(fn: FunctionSpec, layer: LayerSpec, generate: BodyGenerator | null): GeneratedBody {
  if (fn.body.kind === 'text') return { code: fn.body.code };
  if (!generate) throw new BodyError(fn.name, layer.name, 'this function is made of blocks, but no block generator was given.');
  try {
    return generate(fn, layer);
  } catch (e) {
    if (e instanceof BodyError) throw e;
    throw new BodyError(fn.name, layer.name, e instanceof Error ? e.message : String(e));
  }
}

/** One function compiled, with its debug variant when it has one (throws a BodyError). */
export function compileFunction(fn: FunctionSpec, layer: LayerSpec, generate: BodyGenerator | null): CompiledFunction {
  const body = bodyOf(fn, layer, generate);
  return {
    name: fn.name,
    layer: layer.name,
    params: fn.inputs.map((i) => i.name),
    source: functionSource(fn, layer, body.code),
    ...(body.debugCode !== undefined ? { debugSource: functionSource(fn, layer, body.debugCode) } : {}),
  };
}

/** Every function of the controller, compiled, in the controller's function order. */
export function compileController(spec: ControllerSpec, generate: BodyGenerator | null): CompiledFunction[] {
  return allFunctions(spec).map(({ fn, layer }) => compileFunction(fn, layer, generate));
}
