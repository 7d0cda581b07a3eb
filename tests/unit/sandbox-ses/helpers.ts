/** Runs one-function controllers in the fast engine's worker and returns what tick 1 gave. */
import type { FastRunOptions, FastRunResult } from '../../../app/cli/fast-session';
import { runFastSession } from '../../../app/cli/fast-session';
import type { InputSpec } from '../../../app/core/controller/model';
import type { ControllerError } from '../../../app/core/session/types';
import { controller, fn, layer, world } from '../../support/controllers';

/** World inputs every test function receives. */
export const INPUTS: InputSpec[] = [
  { name: 'plan', from: { kind: 'world', input: 'plan' } },
  { name: 'robotPos', from: { kind: 'world', input: 'robotPos' } },
  { name: 'goals', from: { kind: 'world', input: 'goals' } },
];

/** The code of a body-command function that runs `code` first and then moves east. */
const moving = (code: string) => `${code}\nreturn { heading: 0, dx: 1, dy: 0 };`;

/** Runs `code` (with inputs plan, robotPos, goals) for one tick. */
export function runOnce(code: string, options: Partial<FastRunOptions> = {}): Promise<FastRunResult> {
  const c = controller([layer('Bottom', [fn('changePos', 'move', INPUTS, moving(code))])]);
  return runFastSession(world, c, { maxTicks: 1, digests: true, ...options });
}

/** The error tick 1 ended with (the run or the watchdog's). */
export async function errorOf(code: string, options: Partial<FastRunOptions> = {}): Promise<ControllerError | null> {
  const r = await runOnce(code, options);
  return r.stopped ?? r.digests?.[1]?.error ?? null;
}

/** What a function printed on tick 1. */
export async function printedBy(code: string): Promise<string[]> {
  const r = await runOnce(code);
  return (r.digests?.[1]?.printed ?? []).map((l) => l.text);
}
