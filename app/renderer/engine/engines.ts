/**
 * Which sandbox engine the engine Worker runs ticks with.
 *
 * The fast engine (SES compartments, app/core/sandbox/ses.ts) needs `eval` inside this Worker and
 * locks the Worker's whole realm down, which is why it lives here and never on the page. The page's
 * Content-Security-Policy forbids eval; the Worker's script is served with its own policy that
 * allows it (app/main/serve.mjs, app/main/main.ts): in Chromium a dedicated Worker loaded from a
 * same-origin URL takes its policy from its own response. When eval is refused anyway (another
 * server, a policy that does not allow it) or SES cannot start, the Worker runs JS-Interpreter, the
 * reference engine, which gives the same history tick for tick, only slower.
 */
import { createInterpreterSandbox } from '../../core/sandbox/interpreter';
import { createSesSandbox, lockdownForSandbox } from '../../core/sandbox/ses';
import type { SandboxFactory } from '../../core/sandbox/types';
import type { EngineName } from './protocol';

export interface EngineChoice {
  readonly name: EngineName;
  readonly sandbox: SandboxFactory;
  /** Why the fast engine is not running, when it is not. */
  readonly note: string | null;
}

/** A function the fast engine must run correctly before it is trusted with the student's code. */
const PROBE = { name: 'probe', layer: 'probe', params: ['xs'], source: 'function probe(xs) { var s = 0; for (var i = 0; i < xs.length; i++) { s += xs[i]; } return s; }' };

/** Starts the fast engine when it can start here, or falls back to the reference engine. */
export function chooseEngine(wanted: EngineName): EngineChoice {
  const fallback = (note: string | null): EngineChoice => ({ name: 'interpreter', sandbox: createInterpreterSandbox, note });
  if (wanted === 'interpreter') return fallback(null);
  // Ask before locking down: a realm locked down halfway would serve neither engine well.
  if (!evalAllowed()) return fallback("The fast engine needs eval in the engine's Worker, and this page's server does not allow it; ticks run in JS-Interpreter.");
  try {
    lockdownForSandbox();
    const sandbox = createSesSandbox([PROBE]);
    const r = sandbox.call(0, Object.freeze([Object.freeze([1, 2, 3])]), 1000);
    sandbox.dispose();
    if (!r.ok || r.value !== 6) throw new Error(r.ok ? `the probe returned ${String(r.value)}` : r.message);
    return { name: 'fast', sandbox: createSesSandbox, note: null };
  } catch (e) {
    return fallback(`The fast engine could not start (${e instanceof Error ? e.message : String(e)}); ticks run in JS-Interpreter.`);
  }
}

function evalAllowed(): boolean {
  try {
    // eslint-disable-next-line no-new-func -- only asks whether this realm's policy allows eval
    return (new Function('return 1') as () => number)() === 1;
  } catch {
    return false;
  }
}
