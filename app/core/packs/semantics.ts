/**
 * Checks of a pack that its schema cannot express, each with its JSON path: duplicate challenge
 * ids, criteria naming goals a world does not have, locks naming layers or functions the starter
 * does not have, a tick criterion beyond the challenge's tick limit, several variant lists.
 */
import { closest } from '../formats/validator';
import type { WorldSpec } from '../world/world';
import type { Challenge, Pack } from './model';

/** Every problem of a well-formed pack, in file order; empty when it can be used. */
export function packProblems(pack: Pack): { path: string; message: string }[] {
  const problems: { path: string; message: string }[] = [];
  const firstIndex = new Map<string, number>();
  pack.challenges.forEach((c, i) => {
    const at = `$.challenges[${i}]`;
    const first = firstIndex.get(c.id);
    if (first !== undefined) problems.push({ path: `${at}.id`, message: `two challenges have the id "${c.id}" (challenges ${first + 1} and ${i + 1}); ids must differ, because submissions name challenges by id` });
    else firstIndex.set(c.id, i);
    problems.push(...challengeProblems(c, at));
  });
  return problems;
}

function challengeProblems(c: Challenge, at: string): { path: string; message: string }[] {
  const problems: { path: string; message: string }[] = [];
  const add = (path: string, message: string) => problems.push({ path, message });
  const variantsAt = c.criteria.flatMap((cr, j) => (cr.kind === 'variants' ? [j] : []));
  variantsAt.slice(1).forEach((j) => add(`${at}.criteria[${j}]`, 'a challenge takes one "variants" criterion; list every variant world in the first one'));
  const variants = variantsAt.length ? (c.criteria[variantsAt[0]] as { worlds: readonly WorldSpec[] }).worlds : [];
  const worlds: { world: WorldSpec; what: string }[] = [
    { world: c.world, what: 'the challenge world' },
    ...variants.map((world, k) => ({ world, what: `variant world ${k + 1} ("${world.name}")` })),
  ];
  let asksForGoals = false;
  c.criteria.forEach((cr, j) => {
    const cp = `${at}.criteria[${j}]`;
    if (cr.kind === 'reachGoals') {
      if (cr.goals) {
        asksForGoals = true;
        cr.goals.forEach((g, k) => {
          for (const { world, what } of worlds) {
            const names = world.goals.map((x) => x.name);
            if (names.includes(g)) continue;
            const guess = closest(g, names);
            add(`${cp}.goals[${k}]`, `no goal is named "${g}" in ${what}${guess ? ` (did you mean "${guess}"?)` : ''}; its goals are: ${names.join(', ') || 'none'}`);
          }
        });
      } else {
        for (const { world, what } of worlds) {
          if (world.plan.length === 0) add(cp, `this criterion asks for the plan, but ${what} has an empty plan; give the plan or list the goals`);
          else asksForGoals = true;
        }
      }
    }
    if (cr.kind === 'withinTicks' && cr.ticks > c.maxTicks) {
      add(`${cp}.ticks`, `${cr.ticks} ticks is more than the challenge's tick limit (${c.maxTicks}), so runs stop before it; lower it or raise maxTicks`);
    }
  });
  c.criteria.forEach((cr, j) => {
    if (cr.kind === 'withinTicks' && !asksForGoals && worlds.some((w) => w.world.plan.length === 0)) {
      add(`${at}.criteria[${j}]`, 'there is nothing to reach within the ticks: add a "reachGoals" criterion or give the world a plan');
    }
  });
  c.locked.forEach((lock, k) => {
    const lp = `${at}.locked[${k}]`;
    const layerNames = c.starter.layers.map((l) => l.name);
    const layer = c.starter.layers.find((l) => l.name === lock.layer);
    if (!layer) {
      const guess = closest(lock.layer, layerNames);
      add(`${lp}.layer`, `the starter has no layer "${lock.layer}"${guess ? ` (did you mean "${guess}"?)` : ''}; its layers are: ${layerNames.join(', ')}`);
      return;
    }
    if (lock.function !== undefined && !layer.functions.some((f) => f.name === lock.function)) {
      const names = layer.functions.map((f) => f.name);
      const guess = closest(lock.function, names);
      add(`${lp}.function`, `layer "${layer.name}" of the starter has no function "${lock.function}"${guess ? ` (did you mean "${guess}"?)` : ''}; its functions are: ${names.join(', ') || 'none'}`);
    }
  });
  return problems;
}
