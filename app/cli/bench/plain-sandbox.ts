/**
 * A reference "sandbox" that runs compiled functions as plain JavaScript in the host realm, with
 * no isolation and no step budget. It exists only as the native baseline for benchmarks and for
 * cross-checking the real engines in tests; the app never uses it, and the CLI only in `bench`.
 */
import { API } from '../../core/sandbox/api';
import type { CompiledFunction, Sandbox, SandboxFactory } from '../../core/sandbox/types';
import { deepFreeze } from '../../core/values';

export const createPlainSandbox: SandboxFactory = (functions: readonly CompiledFunction[]): Sandbox => {
  let output: string[] = [];
  const names = [...Object.keys(API), 'print', '__block'];
  const natives = [
    ...Object.values(API).map((e) => e.fn),
    (x: unknown) => output.push(typeof x === 'string' ? x : JSON.stringify(x)),
    () => undefined,
  ];
  // eslint-disable-next-line no-new-func -- the unsandboxed baseline, by definition
  const make = new Function(...names, `return [${functions.map((f) => `(${f.source})`).join(',\n')}];`) as (...a: unknown[]) => ((...args: unknown[]) => unknown)[];
  const compiled = make(...natives);
  return {
    call(index, args) {
      output = [];
      try {
        const value = deepFreeze(compiled[index](...args));
        return { ok: true, value, output, steps: 0 };
      } catch (e) {
        return { ok: false, kind: 'exception', message: String(e), output, blockId: null };
      }
    },
    dispose() {},
  };
};
