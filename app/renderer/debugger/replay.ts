/**
 * Builds a replay of one function at one tick from what the page has: the controller (its code is
 * generated here, on the page, as for `load`), the function's inputs at that tick (the arc rows
 * whose `to` is the function) and what the run recorded for it (an arc from it at that tick, a
 * previous-tick arc from it at the next tick, or the error that stopped the run).
 *
 * The arc rows hold exactly what the function received: the engine computes each row with the
 * same argument sources as the tick (Session.arcValue), so a previous-tick arc's row at tick t is
 * its source's output at t-1 (its initial value at tick 1), and world inputs are read from the
 * world after tick t-1, edits included (SPEC T2, T4, T11).
 */
import { compileFunction } from '../../core/controller/compile';
import type { ControllerSpec, FunctionSpec, LayerSpec } from '../../core/controller/model';
import { DEFAULT_STEP_BUDGET } from '../../core/controller/model';
import type { StepperOptions } from '../../core/sandbox/stepper';
import type { CompiledFunction } from '../../core/sandbox/types';
import type { ControllerError } from '../../core/session/types';
import { generateBody } from '../../../blocks/generate';
import type { ArcRow } from '../engine/client';

/** What the run did in the function at that tick, when the page can know it. */
export type Recorded = { readonly kind: 'value'; readonly value: unknown } | { readonly kind: 'error'; readonly error: ControllerError } | { readonly kind: 'unknown'; readonly why: string };

export interface ReplayPlan {
  readonly layer: string;
  readonly function: string;
  readonly tick: number;
  readonly options: StepperOptions;
  readonly recorded: Recorded;
  /** The function is written as text: it has no blocks to stop at. */
  readonly text: boolean;
}

/** The function and its layer in the controller, or null. */
export function findFunction(spec: ControllerSpec, layer: string, name: string): { fn: FunctionSpec; layer: LayerSpec } | null {
  const l = spec.layers.find((x) => x.name === layer) ?? spec.layers.find((x) => x.functions.some((f) => f.name === name));
  const fn = l?.functions.find((f) => f.name === name);
  return l && fn ? { fn, layer: l } : null;
}

/** The function compiled with its debug variant (throws a BodyError with a readable message). */
export function compileOne(fn: FunctionSpec, layer: LayerSpec): CompiledFunction {
  return compileFunction(fn, layer, generateBody);
}

/** The inputs `fn` received at a tick, in its parameter order, from that tick's arc rows. */
export function inputsFrom(fn: FunctionSpec, rows: readonly ArcRow[]): unknown[] {
  return fn.inputs.map((inp) => {
    const row = rows.find((r) => r.to === fn.name && r.input === inp.name);
    if (!row) throw new Error(`The run has no value for the input "${inp.name}" of ${fn.name}.`);
    return row.value;
  });
}

/**
 * What the run recorded for `name` at `tick`: from this tick's rows, the next tick's (asked for
 * only when needed), or the tick's error.
 */
export async function recordedOutput(name: string, tick: number, rows: readonly ArcRow[], error: ControllerError | null, nextRows: (() => Promise<readonly ArcRow[]>) | null): Promise<Recorded> {
  if (error) {
    if (error.function === name) return { kind: 'error', error };
  }
  const same = rows.find((r) => r.from === name && !r.previousTick);
  if (same && same.value !== undefined) return { kind: 'value', value: same.value };
  if (error) return { kind: 'unknown', why: `The run stopped at this tick with an error in ${error.function ?? 'the controller'}.` };
  if (nextRows) {
    const next = (await nextRows()).find((r) => r.from === `previous.${name}`);
    if (next && next.value !== undefined) return { kind: 'value', value: next.value };
  }
  return { kind: 'unknown', why: 'No arc carries this function’s output at this tick, so there is nothing to compare with.' };
}

/** Everything a replay needs; throws an Error with a readable message when it cannot be made. */
export function planReplay(spec: ControllerSpec, layerName: string, name: string, tick: number, rows: readonly ArcRow[], recorded: Recorded): ReplayPlan {
  const found = findFunction(spec, layerName, name);
  if (!found) throw new Error(`The controller has no function “${name}”.`);
  const { fn, layer } = found;
  const compiled = compileOne(fn, layer);
  return {
    layer: layer.name,
    function: fn.name,
    tick,
    recorded,
    text: compiled.debugSource === undefined,
    options: {
      fn: compiled,
      args: inputsFrom(fn, rows),
      budget: spec.stepBudget ?? DEFAULT_STEP_BUDGET,
      output: fn.output,
      layerVariables: layer.variables.map((v) => v.name),
    },
  };
}
