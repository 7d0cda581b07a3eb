/**
 * Judging a challenge: every criterion becomes a reason that says what was asked and exactly what
 * happened ("reached o103 at tick 140", "crashed at tick 171: the wall at (70,-5)-(70,25)"). The
 * verdict passes when every reason passes. With variant worlds, each run criterion is judged on
 * each world, and its reasons name the world.
 */
import type { ControllerSpec } from '../controller/model';
import { blockTally, isLocked } from './blocks';
import { list, wall } from './describe';
import { lockChanges } from './locks';
import type { Challenge, Criterion, Reason, Verdict } from './model';
import type { ChallengeRun, SetupFailure } from './runs';

type RunCriterion = Extract<Criterion, { kind: 'reachGoals' | 'withinTicks' | 'noCrash' | 'noError' }>;
const isRunCriterion = (c: Criterion): c is RunCriterion => c.kind === 'reachGoals' || c.kind === 'withinTicks' || c.kind === 'noCrash' || c.kind === 'noError';

/** Judges `controller` on `challenge`, given its runs (runs.ts) or why it could not run. */
export function judge(challenge: Challenge, controller: ControllerSpec, runs: readonly ChallengeRun[] | SetupFailure): Verdict {
  const reasons: Reason[] = [];
  if (challenge.locked.length) reasons.push(lockReason(challenge, controller));
  for (const c of challenge.criteria) {
    if (c.kind === 'hasFunction') reasons.push(hasFunctionReason(controller, c.layer, c.function));
    if (c.kind === 'maxBlocks') reasons.push(maxBlocksReason(challenge, controller, c.blocks, c.scope));
  }
  if ('setupError' in runs) {
    reasons.push({ criterion: 'the controller runs', passed: false, detail: runs.setupError });
  } else {
    const runCriteria = challenge.criteria.filter(isRunCriterion);
    const named = runs.length > 1;
    const failedWorlds: string[] = [];
    for (const run of runs) {
      const here = runCriteria.map((c) => ({ ...judgeRun(c, run, runCriteria), ...(named ? { world: run.label } : {}) }));
      if (here.some((r) => !r.passed)) failedWorlds.push(run.label);
      reasons.push(...here);
    }
    if (named) {
      reasons.push({
        criterion: `works on the challenge world and ${runs.length - 1} ${runs.length === 2 ? 'variant' : 'variants'}`,
        passed: failedWorlds.length === 0,
        detail: failedWorlds.length ? `failed on ${list(failedWorlds)}` : `passed on ${list(runs.map((r) => r.label))}`,
      });
    }
  }
  return { passed: reasons.every((r) => r.passed), reasons };
}

/**
 * A verdict in one line, for tables: the failed reasons' details, or for a pass the facts of the
 * run in the challenge world. A detail (or, in the challenge world, a part of one between
 * semicolons) repeated by two criteria is said once.
 */
export function verdictSummary(v: Verdict): string {
  const facts = v.reasons.filter((r) => r.world === undefined && r.criterion !== 'locked parts unchanged');
  const shown = v.passed ? facts : v.reasons.filter((r) => !r.passed);
  // Details about a variant world stay whole behind their "on ..." prefix; the others split into parts.
  const texts = shown.flatMap((r) => (r.world !== undefined ? [`on ${r.world}: ${r.detail}`] : r.detail.split('; ')));
  return [...new Set(texts)].join('; ');
}

function lockReason(challenge: Challenge, controller: ControllerSpec): Reason {
  const changes = lockChanges(challenge.starter, controller, challenge.locked);
  const names = challenge.locked.map((l) => (l.function === undefined ? `layer "${l.layer}"` : `function "${l.function}" (layer "${l.layer}")`));
  return {
    criterion: 'locked parts unchanged',
    passed: changes.length === 0,
    detail: changes.length ? changes.join('; ') : `${list(names)} unchanged`,
  };
}

function hasFunctionReason(controller: ControllerSpec, layerName: string, fnName: string): Reason {
  const criterion = `function "${fnName}" in layer "${layerName}"`;
  const layer = controller.layers.find((l) => l.name === layerName);
  if (layer?.functions.some((f) => f.name === fnName)) return { criterion, passed: true, detail: `layer "${layerName}" has the function "${fnName}"` };
  const elsewhere = controller.layers.find((l) => l.functions.some((f) => f.name === fnName));
  const detail = !layer
    ? `there is no layer "${layerName}" (the layers are ${list(controller.layers.map((l) => `"${l.name}"`))})`
    : `layer "${layerName}" has no function "${fnName}"${elsewhere ? ` (it is in layer "${elsewhere.name}")` : ''}`;
  return { criterion, passed: false, detail };
}

function maxBlocksReason(challenge: Challenge, controller: ControllerSpec, most: number, scope: 'editable' | 'all'): Reason {
  const criterion = `at most ${most} blocks`;
  const where = scope === 'all' ? 'the controller' : 'the editable functions';
  const tally = blockTally(controller, (fn, layer) => scope === 'all' || !isLocked(challenge.locked, layer.name, fn.name));
  if (tally.text.length) {
    const names = list(tally.text.map((t) => `"${t.name}" (layer "${t.layer}")`));
    return { criterion, passed: false, detail: `cannot count the blocks of ${names}: written as text, not blocks` };
  }
  const passed = tally.total <= most;
  const parts = tally.perFunction.filter((f) => f.blocks > 0).map((f) => `${f.name} ${f.blocks}`);
  return { criterion, passed, detail: `${tally.total} blocks in ${where} (at most ${most})${passed || !parts.length ? '' : `: ${parts.join(', ')}`}` };
}

/** The tick each goal was reached at, or null: in turn ("plan") or each on its own ("any"). */
export function reachTicks(run: ChallengeRun, goals: readonly string[], order: 'plan' | 'any'): (number | null)[] {
  const r2 = run.goalRadius * run.goalRadius;
  const within = (name: string, t: number) => {
    const g = run.world.goals.find((x) => x.name === name);
    if (!g) return false;
    const dx = g.x - run.path[t][0];
    const dy = g.y - run.path[t][1];
    return dx * dx + dy * dy <= r2;
  };
  const first = (name: string, from: number): number | null => {
    for (let t = from; t < run.path.length; t++) if (within(name, t)) return t;
    return null;
  };
  if (order === 'any') return goals.map((g) => first(g, 0));
  // As the world tracks its plan (SPEC T8): step i counts from the tick after step i-1.
  const ticks: (number | null)[] = [];
  let from = 0;
  for (const g of goals) {
    const t = from === -1 ? null : first(g, from);
    ticks.push(t);
    from = t === null ? -1 : t + 1;
  }
  return ticks;
}

/** Why the run stopped, for goals it did not reach. */
function ending(run: ChallengeRun): string {
  if (run.crash) return `the robot crashed at tick ${run.crash.tick}`;
  if (run.error) return `an error stopped the run at tick ${run.error.tick}`;
  if (run.ticks >= run.maxTicks) return `not within ${run.maxTicks} ticks`;
  return `the run ended at tick ${run.ticks}`;
}

function goalsOf(c: Extract<Criterion, { kind: 'reachGoals' }>, run: ChallengeRun): readonly string[] {
  return c.goals ?? run.world.plan;
}

function reachedText(goals: readonly string[], ticks: readonly (number | null)[], run: ChallengeRun): string {
  const reached = goals.flatMap((g, i) => (ticks[i] === null ? [] : [`${g} at tick ${ticks[i]}`]));
  const missed = goals.filter((_, i) => ticks[i] === null);
  const parts: string[] = [];
  if (reached.length) parts.push(`reached ${reached.join(', ')}`);
  if (missed.length) parts.push(`${list(missed)} not reached (${ending(run)})`);
  return parts.join('; ');
}

function judgeRun(c: RunCriterion, run: ChallengeRun, all: readonly RunCriterion[]): Reason {
  switch (c.kind) {
    case 'reachGoals': {
      const goals = goalsOf(c, run);
      const ticks = reachTicks(run, goals, c.order);
      const criterion = c.goals ? `reach ${goals.join(', ')} ${c.order === 'plan' ? 'in order' : 'in any order'}` : `reach the plan (${goals.join(', ')})${c.order === 'plan' ? ' in order' : ' in any order'}`;
      return { criterion, passed: ticks.every((t) => t !== null), detail: reachedText(goals, ticks, run) };
    }
    case 'withinTicks': {
      const reach = all.filter((x): x is Extract<RunCriterion, { kind: 'reachGoals' }> => x.kind === 'reachGoals');
      const asked = reach.length ? reach.map((r) => ({ goals: goalsOf(r, run), order: r.order })) : [{ goals: run.world.plan, order: 'plan' as const }];
      const found = asked.flatMap((a) => {
        const ticks = reachTicks(run, a.goals, a.order);
        return a.goals.map((g, i) => ({ goal: g, tick: ticks[i] }));
      });
      const criterion = `within ${c.ticks} ticks`;
      const missed = found.filter((f) => f.tick === null).map((f) => f.goal);
      if (missed.length) return { criterion, passed: false, detail: `${list([...new Set(missed)])} not reached (${ending(run)})` };
      const last = found.reduce((a, b) => ((b.tick ?? 0) > (a.tick ?? 0) ? b : a), found[0]);
      if (!last) return { criterion, passed: true, detail: 'no goals to reach' };
      const passed = (last.tick ?? 0) <= c.ticks;
      return { criterion, passed, detail: `the last goal, ${last.goal}, was reached at tick ${last.tick}${passed ? ` (limit ${c.ticks})` : `, after tick ${c.ticks}`}` };
    }
    case 'noCrash':
      return run.crash
        ? { criterion: 'no crash', passed: false, detail: `crashed at tick ${run.crash.tick}: the wall at ${wall(run.crash.wall)}` }
        : { criterion: 'no crash', passed: true, detail: `no crash in ${run.ticks} ticks` };
    case 'noError':
      return run.error
        ? { criterion: 'no error', passed: false, detail: `at tick ${run.error.tick}: ${run.error.message}` }
        : { criterion: 'no error', passed: true, detail: `no error in ${run.ticks} ticks` };
  }
}

