/**
 * The controller as a dataflow graph: which functions feed which within one tick, the order to
 * run them in, and, when there is a cycle, the functions on it, named for the student.
 */
import type { ControllerSpec, PlacedFunction } from './model';
import { allFunctions } from './model';

/** The result of ordering: a run order (indices into allFunctions) or a cycle. */
export type Ordering = { readonly ok: true; readonly order: readonly number[] } | { readonly ok: false; readonly cycle: readonly PlacedFunction[] };

/**
 * Orders the functions so that each runs after every function it reads this tick. Previous-tick
 * arcs impose no order. Ties keep the file's order (top layer first), so traces are stable.
 * Assumes arcs name existing functions (see validate.ts); unknown names are ignored here.
 */
export function orderFunctions(spec: ControllerSpec): Ordering {
  const fns = allFunctions(spec);
  const index = new Map(fns.map((f, i) => [f.fn.name, i]));
  const deps = fns.map((f) =>
    f.fn.inputs.flatMap((inp) => (inp.from.kind === 'function' && index.has(inp.from.function) ? [index.get(inp.from.function)!] : [])),
  );
  const state = new Uint8Array(fns.length); // 0 new, 1 on the stack, 2 done
  const order: number[] = [];
  const stack: number[] = [];

  // Depth-first in file order; a node is emitted after its dependencies.
  const visit = (i: number): number[] | null => {
    if (state[i] === 2) return null;
    if (state[i] === 1) return stack.slice(stack.indexOf(i));
    state[i] = 1;
    stack.push(i);
    for (const d of deps[i]) {
      const cycle = visit(d);
      if (cycle) return cycle;
    }
    stack.pop();
    state[i] = 2;
    order.push(i);
    return null;
  };
  for (let i = 0; i < fns.length; i++) {
    const cycle = visit(i);
    if (cycle) return { ok: false, cycle: cycle.map((c) => fns[c]) };
  }
  return { ok: true, order };
}

/** Explains a cycle: the functions on it and the fix. */
export function explainCycle(cycle: readonly PlacedFunction[]): string {
  // The stack lists each function before the one it reads: show the flow of values instead.
  const flow = [...cycle].reverse();
  const names = flow.map((f) => `"${f.fn.name}" (layer "${f.layer.name}")`);
  const path = [...flow, flow[0]].map((f) => f.fn.name).join(' -> ');
  const first = flow[0].fn.name;
  const second = flow.length > 1 ? flow[1].fn.name : first;
  return (
    `The functions ${names.join(', ')} read each other's outputs in a circle within one tick (${path}), ` +
    'so none of them can run first. Take one of these arcs from the previous tick instead ' +
    `(for example, let "${second}" read "${first}" from the previous tick).`
  );
}
