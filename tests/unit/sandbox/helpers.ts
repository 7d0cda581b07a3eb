/** Small builders for the sandbox tests. */
import { createInterpreterSandbox } from '../../../app/core/sandbox/interpreter';
import type { CompiledFunction, Sandbox, SandboxResult } from '../../../app/core/sandbox/types';

/** A strict function declaration, as the controller compiler emits it. */
export function fn(name: string, params: string[], body: string, layer = 'Layer'): CompiledFunction {
  return { name, layer, params, source: `function ${name}(${params.join(', ')}) {\n'use strict';\n${body}\n}` };
}

/** A sandbox holding one function. */
export function single(params: string[], body: string): Sandbox {
  return createInterpreterSandbox([fn('f', params, body)]);
}

/** Runs a one-function sandbox once. */
export function run(params: string[], body: string, args: unknown[] = [], budget = 100_000): SandboxResult {
  const sandbox = single(params, body);
  try {
    return sandbox.call(0, args, budget);
  } finally {
    sandbox.dispose();
  }
}

/** The value of a successful result (fails the test with the message otherwise). */
export function valueOf(r: SandboxResult): unknown {
  if (!r.ok) throw new Error(`expected success, got ${r.kind}: ${r.message}`);
  return r.value;
}
