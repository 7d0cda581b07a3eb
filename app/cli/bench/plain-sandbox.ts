/**
 * A reference "sandbox" that runs compiled functions as plain JavaScript in the host realm, with
 * no isolation and no step budget. It exists only as the native baseline for benchmarks and for
 * cross-checking the real engines in tests; the app never uses it, and the CLI only in `bench`.
 */
import { API } from '../../core/sandbox/api';
import type { CompiledFunction, Sandbox, SandboxFactory } from '../../core/sandbox/types';
import { deepFreeze } from '../../core/values';

type Native = (...args: unknown[]) => unknown;

/**
 * The functions' generated code as plain JavaScript functions, calling the API helpers directly;
 * `print` writes to `output.lines`. Nothing is checked, copied or frozen: the benchmark's baseline.
 *
 * Run it in a realm that is not locked down: after SES's `lockdown()`, every read of a global
 * (`Math`, ...) from host code costs several times more, which would flatter the sandbox.
 */
export function plainFunctions(functions: readonly CompiledFunction[], output: { lines: string[] } = { lines: [] }): Native[] {
  const names = [...Object.keys(API), 'print', '__block'];
  const natives = [
    ...Object.values(API).map((e) => e.fn),
    (x: unknown) => output.lines.push(typeof x === 'string' ? x : JSON.stringify(x)),
    () => undefined,
  ];
  // eslint-disable-next-line no-new-func -- the unsandboxed baseline, by definition
  const make = new Function(...names, `return [${functions.map((f) => `(${f.source})`).join(',\n')}];`) as (...a: unknown[]) => Native[];
  return make(...natives);
}

export const createPlainSandbox: SandboxFactory = (functions: readonly CompiledFunction[]): Sandbox => {
  const output = { lines: [] as string[] };
  const compiled = plainFunctions(functions, output);
  return {
    call(index, args) {
      output.lines = [];
      try {
        const value = deepFreeze(compiled[index](...args));
        return { ok: true, value, output: output.lines, steps: 0 };
      } catch (e) {
        return { ok: false, kind: 'exception', message: String(e), output: output.lines, blockId: null };
      }
    },
    dispose() {},
  };
};
