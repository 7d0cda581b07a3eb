/** The teacher's draft: edits, and a pack file parsePack accepts (or problems by challenge and field). */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { parseController, parseWorld } from '../../../app/core/formats';
import { parsePack, TOOLBOX_CATEGORIES } from '../../../app/core/packs';
import {
  addChallenge,
  checkDraft,
  criteriaOf,
  draftOfPack,
  emptyDraft,
  functionLocked,
  layerLocked,
  move,
  moveChallenge,
  packFileName,
  packText,
  readDraft,
  removeChallenge,
  setCategory,
  setCriteria,
  setFunctionLock,
  setLayerLock,
  uniqueId,
  updateChallenge,
} from '../../../app/renderer/packs/draft';

const ROOT = join(__dirname, '../../..');
const read = <T>(r: { ok: true; value: T } | { ok: false; problems: unknown }): T => {
  if (!r.ok) throw new Error(JSON.stringify(r.problems));
  return r.value;
};
const office = read(parseWorld(readFileSync(join(ROOT, 'examples/worlds/office.world.json'), 'utf8'), 'office.world.json'));
const trap = read(parseWorld(readFileSync(join(ROOT, 'examples/worlds/trap.world.json'), 'utf8'), 'trap.world.json'));
const basic = read(parseController(readFileSync(join(ROOT, 'examples/controllers/basic.controller.json'), 'utf8'), 'basic.controller.json'));

const oneChallenge = () => addChallenge(emptyDraft('Office tour', 'A. Teacher', 'Deliveries.'), office, basic);

test('adding the current world and controller makes a challenge with unique ids and sensible criteria', () => {
  let d = oneChallenge();
  d = addChallenge(d, office, basic);
  expect(d.challenges.map((c) => c.id)).toEqual(['office', 'office-2']);
  expect(uniqueId('Visit a plan!', ['visit-a-plan'])).toBe('visit-a-plan-2');
  expect(criteriaOf(d.challenges[0].criteria)).toEqual([{ kind: 'reachGoals', order: 'plan' }, { kind: 'noCrash' }, { kind: 'noError' }]);
  const r = checkDraft(d);
  expect(r.ok).toBe(true);
  expect(packFileName(d)).toBe('office-tour.pack.json');
});

test('an empty draft is not a pack yet: parsePack says why', () => {
  const r = checkDraft(emptyDraft());
  expect(r.ok).toBe(false);
  if (!r.ok) expect(r.problems.map((p) => p.path)).toContain('$.challenges');
});

test('locks per layer and function, toolbox categories, criteria and hints reach the pack file', () => {
  let d = oneChallenge();
  d = updateChallenge(d, 0, (c) => setLayerLock(c, 'Bottom', true));
  d = updateChallenge(d, 0, (c) => setFunctionLock(c, 'Middle', 'steer', true));
  d = updateChallenge(d, 0, (c) => setCategory(setCategory(c, 'Loops', false), 'Grid', false));
  d = updateChallenge(d, 0, (c) =>
    setCriteria(c, (k) => ({
      ...k,
      reach: { on: true, goals: ['o103', 'storage'], order: 'any' },
      within: { on: true, ticks: 900 },
      maxBlocks: { on: true, blocks: 80, scope: 'all' },
      functions: [{ layer: 'Top', function: 'todo' }],
      variants: [office],
    })),
  );
  d = updateChallenge(d, 0, (c) => ({ ...c, hints: ['first', 'second'], maxTicks: 1500 }));
  const c = d.challenges[0];
  expect(layerLocked(c, 'Bottom')).toBe(true);
  expect(functionLocked(c, 'Bottom', 'whiskerOn')).toBe(true);
  expect(functionLocked(c, 'Middle', 'steer')).toBe(true);
  expect(functionLocked(c, 'Middle', 'arrived')).toBe(false);
  const pack = read(parsePack(packText(d), 'x.pack.json'));
  const pc = pack.challenges[0];
  expect(pc.locked).toEqual([{ layer: 'Bottom' }, { layer: 'Middle', function: 'steer' }]);
  expect(pc.toolbox).toEqual(TOOLBOX_CATEGORIES.filter((k) => k !== 'Loops' && k !== 'Grid'));
  expect(pc.hints).toEqual(['first', 'second']);
  expect(pc.maxTicks).toBe(1500);
  expect(pc.criteria).toEqual([
    { kind: 'reachGoals', goals: ['o103', 'storage'], order: 'any' },
    { kind: 'withinTicks', ticks: 900 },
    { kind: 'noCrash' },
    { kind: 'noError' },
    { kind: 'maxBlocks', blocks: 80, scope: 'all' },
    { kind: 'hasFunction', layer: 'Top', function: 'todo' },
    { kind: 'variants', worlds: [office] },
  ]);
  // Locking a whole layer replaces its single-function locks; offering every category again means "all".
  const relocked = setLayerLock(setFunctionLock(c, 'Middle', 'steer', true), 'Middle', true);
  expect(relocked.locked).toEqual([{ layer: 'Bottom' }, { layer: 'Middle' }]);
  expect(setCategory(setCategory(c, 'Loops', true), 'Grid', true).toolbox).toBeNull();
});

test('problems name the challenge and the field', () => {
  let d = oneChallenge();
  d = updateChallenge(d, 0, (c) => setCriteria(c, (k) => ({ ...k, reach: { on: true, goals: ['o1O3'], order: 'plan' }, within: { on: true, ticks: 5000 } })));
  d = updateChallenge(d, 0, (c) => setLayerLock(c, 'Bottm', true));
  const r = checkDraft(d);
  expect(r.ok).toBe(false);
  if (r.ok) return;
  expect(r.problems.map((p) => p.path)).toEqual(['$.challenges[0].criteria[0].goals[0]', '$.challenges[0].criteria[1].ticks', '$.challenges[0].locked[0].layer']);
  expect(r.problems.every((p) => p.message.startsWith('challenge "office": '))).toBe(true);
  expect(r.problems[0].message).toContain('no goal is named "o1O3"');
  // A blank hint is a problem of the file's shape.
  const blank = checkDraft(updateChallenge(oneChallenge(), 0, (c) => ({ ...c, hints: ['  '] })));
  expect(blank.ok).toBe(false);
  if (!blank.ok) {
    expect(blank.problems.map((p) => p.path)).toEqual(['$.challenges[0].hints[0]']);
    expect(blank.problems[0].message).toBe('challenge "office": the hint must not be empty');
  }
});

test('challenges and hints reorder and delete', () => {
  let d = addChallenge(oneChallenge(), trap, basic);
  d = moveChallenge(d, 1, -1);
  expect(d.challenges.map((c) => c.id)).toEqual(['robot-trap', 'office']);
  expect(moveChallenge(d, 0, -1).challenges.map((c) => c.id)).toEqual(['robot-trap', 'office']);
  d = removeChallenge(d, 0);
  expect(d.challenges.map((c) => c.id)).toEqual(['office']);
  expect(move(['a', 'b', 'c'], 2, -1)).toEqual(['a', 'c', 'b']);
  expect(move(['a', 'b', 'c'], 2, 1)).toEqual(['a', 'b', 'c']);
});

test('the intro pack goes through the editor unchanged in meaning', () => {
  const intro = read(parsePack(readFileSync(join(ROOT, 'examples/packs/intro.pack.json'), 'utf8'), 'intro.pack.json'));
  const again = read(parsePack(packText(draftOfPack(intro)), 'again.pack.json'));
  // The editor lists criteria in its own order (reach, ticks, crash, error, blocks, functions, variants).
  const sorted = (p: typeof intro) => ({ ...p, challenges: p.challenges.map((c) => ({ ...c, criteria: [...c.criteria].sort((a, b) => JSON.stringify(a).localeCompare(JSON.stringify(b))) })) });
  expect(sorted(again)).toEqual(sorted(intro));
});

test('a stored draft reads back, even one that is not a valid pack yet', () => {
  let d = oneChallenge();
  d = updateChallenge(d, 0, (c) => ({ ...c, hints: ['one'], locked: [{ layer: 'Nope' }] }));
  const back = readDraft(packText(d));
  expect(back).toEqual(d);
  expect(readDraft('not json')).toBeNull();
  expect(readDraft('{"format": "layerbot-world"}')).toBeNull();
});
