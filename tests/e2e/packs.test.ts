/**
 * Challenge packs in the built app: a student works through two challenges of the intro pack
 * (the starter fails with specific reasons, the reference solution passes, hints, progress kept
 * over a reload, a submission exported); a malformed pack is reported by challenge and field and
 * the app keeps working; a teacher makes a challenge from the current world and controller and
 * exports a pack that parsePack accepts.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Browser, Page } from 'playwright-core';
import { parsePack, parseSubmission } from '../../app/core/packs';
import type { LayerbotPackTestHooks } from '../../app/renderer/packs/test-hooks';
import { launchApp, openApp, state } from './support';

jest.setTimeout(120_000);

const ROOT = join(__dirname, '../..');
const PACK_TEXT = readFileSync(join(ROOT, 'examples/packs/intro.pack.json'), 'utf8');
const SOLUTIONS = JSON.parse(readFileSync(join(ROOT, 'examples/packs/intro.solution.submission.json'), 'utf8')) as { controllers: Record<string, unknown> };

let browser: Browser;
let page: Page;
let pageErrors: string[];

/** What the pack test hooks report (app/renderer/packs/test-hooks.ts). */
type PackState = ReturnType<LayerbotPackTestHooks['state']>;

const packState = (): Promise<PackState> => page.evaluate(() => window.layerbotPackTest!.state());

beforeAll(async () => {
  ({ browser, page, pageErrors } = await launchApp());
});

afterAll(() => browser?.close());

/** Presses Check and waits for the verdict; returns it with the time the Check took. */
async function check(): Promise<{ verdict: NonNullable<PackState['verdict']>; ms: number }> {
  const before = (await packState()).checks.length;
  await page.click('#pack-check');
  await page.waitForFunction((n) => window.layerbotPackTest!.state().checks.length > n && !window.layerbotPackTest!.state().checking, before, { timeout: 60_000 });
  const s = await packState();
  return { verdict: s.verdict!, ms: s.checks[s.checks.length - 1].ms };
}

async function loadSolution(id: string): Promise<void> {
  expect(await page.evaluate((t) => window.layerbotPackTest!.loadController(t), JSON.stringify(SOLUTIONS.controllers[id]))).toBe(true);
}

const failed = (v: NonNullable<PackState['verdict']>) => v.reasons.filter((r) => !r.passed).map((r) => `${r.criterion}: ${r.detail}`);

describe('student', () => {
  test('opens the intro pack from File › Example packs: the challenges, the first one loaded with its locks', async () => {
    await page.click('#file-button');
    await page.click('#menu-example-packs [data-example="intro.pack.json"]');
    await page.waitForFunction(() => window.layerbotPackTest!.state().pack !== null);
    const s = await packState();
    expect(s.pack).toBe('Layered control, step by step');
    expect(s.current).toBe('steer-one');
    expect(Object.values(s.statuses)).toEqual(Array(8).fill('not started'));
    expect(await page.locator('#pack-card .challenge-list button').count()).toBe(8);
    expect((await state(page)).worldName).toBe('One flag');
    // Locked parts and the toolbox go to the controller editor.
    expect(s.restrictions?.locked).toEqual([{ layer: 'Top' }, { layer: 'Bottom' }, { layer: 'Middle', function: 'arrived' }]);
    expect(s.restrictions?.toolbox).not.toContain('Loops');
    await page.waitForSelector('#challenge-panel:not([hidden])');
    expect(await page.locator('#challenge-panel .challenge-desc').textContent()).toContain('steer');
  });

  test('the starter fails with specific reasons, on the challenge world and its hidden variants', async () => {
    const { verdict, ms } = await check();
    console.log(`Check of the steer-one starter: ${Math.round(ms)} ms`);
    expect(verdict.passed).toBe(false);
    expect(failed(verdict)).toContain('reach the plan (flag) in order: flag not reached (not within 300 ticks)');
    expect(verdict.reasons.some((r) => r.world === 'variant 2 ("One flag (behind)")')).toBe(true);
    await page.waitForSelector('#challenge-verdict .reason[data-passed="false"]');
    const text = await page.locator('#challenge-verdict').innerText();
    expect(text).toContain('Not passed yet');
    expect(text).toContain('✗');
    expect(text).toContain('✓');
    expect((await packState()).statuses['steer-one']).toBe('attempted');
  });

  test('hints are revealed one at a time', async () => {
    expect(await page.locator('#challenge-panel .challenge-hints li').count()).toBe(0);
    await page.click('#pack-hint');
    await page.waitForSelector('#challenge-panel .challenge-hints li');
    expect(await page.locator('#challenge-panel .challenge-hints li').count()).toBe(1);
    expect(await page.locator('#pack-hint').textContent()).toBe('Show hint 2 of 3');
  });

  test('the reference solution passes', async () => {
    await loadSolution('steer-one');
    const { verdict, ms } = await check();
    console.log(`Check of the steer-one solution: ${Math.round(ms)} ms`);
    expect(failed(verdict)).toEqual([]);
    expect(verdict.passed).toBe(true);
    expect(await page.locator('#challenge-verdict .verdict-head').innerText()).toMatch(/^Passed: all \d+ checks hold/);
    expect((await packState()).statuses['steer-one']).toBe('passed');
    expect(await page.locator('#pack-card [data-challenge="steer-one"]').getAttribute('data-status')).toBe('passed');
  });

  test('a second challenge: a run that ends checks the work; the crash names its tick and wall', async () => {
    await page.click('#pack-card [data-challenge="whisker"]');
    await page.waitForFunction(() => window.layerbotPackTest!.state().current === 'whisker');
    expect((await state(page)).worldName).not.toBe('One flag');
    const before = (await packState()).checks.length;
    await page.locator('#speed').fill('10');
    await page.click('#btn-run');
    await page.waitForFunction((n) => window.layerbotPackTest!.state().checks.length > n && !window.layerbotPackTest!.state().checking, before, { timeout: 60_000 });
    const v = (await packState()).verdict!;
    expect(v.passed).toBe(false);
    expect(failed(v)).toContain('no crash: crashed at tick 20: the wall at (-12,20)-(10,20)');
    await loadSolution('whisker');
    const { verdict, ms } = await check();
    console.log(`Check of the whisker solution: ${Math.round(ms)} ms`);
    expect(verdict.passed).toBe(true);
  });

  test('switching challenges keeps each challenge’s work', async () => {
    await page.click('#pack-card [data-challenge="steer-one"]');
    await page.waitForFunction(() => window.layerbotPackTest!.state().current === 'steer-one');
    const { verdict } = await check();
    expect(verdict.passed).toBe(true); // the solution loaded earlier, not the starter
  });

  test('progress, work and hints persist after a reload', async () => {
    await page.reload();
    await openApp(page);
    await page.waitForFunction(() => window.layerbotPackTest!.state().pack !== null);
    const s = await packState();
    expect(s.current).toBe('steer-one');
    expect(s.statuses).toMatchObject({ 'steer-one': 'passed', whisker: 'passed', 'visit-plan': 'not started' });
    expect(await page.locator('#pack-card .pack-progress').innerText()).toContain('2 of 8 passed');
    expect(await page.locator('#challenge-panel .challenge-hints li').count()).toBe(1);
    await page.click('#pack-card [data-challenge="whisker"]');
    await page.waitForFunction(() => window.layerbotPackTest!.state().current === 'whisker');
    expect((await check()).verdict.passed).toBe(true);
  });

  test('exports a submission with the student’s name that the grader reads', async () => {
    await page.fill('#pack-student', 'Ada Lovelace');
    await page.locator('#pack-student').blur();
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#pack-export')]);
    expect(download.suggestedFilename()).toBe('ada-lovelace-layered-control-step-by-step.submission.json');
    const text = readFileSync((await download.path())!, 'utf8');
    const sub = parseSubmission(text, 'x.submission.json');
    if (!sub.ok) throw new Error(JSON.stringify(sub.problems));
    expect(sub.value.student).toBe('Ada Lovelace');
    expect(sub.value.pack).toBe('Layered control, step by step');
    expect(Object.keys(sub.value.controllers).sort()).toEqual(['steer-one', 'whisker']);
  });
});

describe('a malformed pack', () => {
  test('is reported by challenge and field, and the app keeps working', async () => {
    const bad = JSON.parse(PACK_TEXT) as { challenges: { criteria: unknown[] }[] };
    bad.challenges[1].criteria[0] = { kind: 'reachGoals', goals: ['o1O3'], order: 'plan' };
    const ok = await page.evaluate((t) => window.layerbotPackTest!.openPackText(t, 'broken.pack.json'), JSON.stringify(bad));
    expect(ok).toBe(false);
    const box = await page.locator('#pack-problems').innerText();
    expect(box).toContain('broken.pack.json could not be opened as a pack');
    expect(box).toContain('challenge "visit-plan": no goal is named "o1O3"');
    expect(box).toContain('$.challenges[1].criteria[0].goals[0]');
    // Not JSON at all.
    expect(await page.evaluate(() => window.layerbotPackTest!.openPackText('{"format": "layerbot-pack", ', 'cut.pack.json'))).toBe(false);
    expect(await page.locator('#pack-problems').innerText()).toContain('cut.pack.json could not be opened as a pack');
    // The open pack is still open, and the robot still runs.
    expect((await packState()).pack).toBe('Layered control, step by step');
    const before = (await state(page)).latestTick;
    await page.click('#btn-reset');
    await page.waitForFunction(() => window.layerbotTest!.state().latestTick === 0);
    await page.click('#btn-step');
    await page.waitForFunction(() => window.layerbotTest!.state().latestTick === 1);
    expect(before).toBeGreaterThanOrEqual(0);
    expect(pageErrors).toEqual([]);
  });
});

describe('teacher', () => {
  test('makes a challenge from the current world and controller, previews it and exports a pack parsePack accepts', async () => {
    await page.click('#pack-close');
    await page.waitForFunction(() => window.layerbotPackTest!.state().pack === null);
    expect((await packState()).restrictions).toBeNull();
    // The world and controller to turn into a challenge.
    await page.click('#file-button');
    await page.click('#menu-example-worlds [data-example="office.world.json"]');
    await page.click('#file-button');
    await page.click('#menu-example-controllers [data-example="basic.controller.json"]');
    await page.waitForFunction(() => window.layerbotTest!.state().worldName === 'Office' && window.layerbotTest!.state().hasController);
    await page.click('#file-button');
    await page.click('[data-action="pack-editor"]');
    await page.waitForSelector('.pack-editor #pe-title');
    await page.fill('#pe-title', 'Office deliveries');
    await page.fill('#pe-author', 'A. Teacher');
    await page.fill('#pe-description', 'Deliver the mail around the office.');
    await page.click('#pe-add-challenge');
    await page.waitForSelector('.pe-challenge');
    await page.fill('#pe-c-title', 'Deliver along the plan');
    await page.check('#pe-lock-layer-Bottom');
    await page.uncheck('#pe-tb-Loops');
    await page.check('#pe-crit-within');
    await page.fill('#crit-within-ticks', '900');
    await page.click('#crit-add-variant');
    await page.click('#pe-add-hint');
    await page.fill('#hint-0', 'Follow the plan one goal at a time.');
    await page.waitForSelector('#pe-problems.ok');
    // Preview as a student: the challenge opens and passes with the starter.
    await page.click('#pe-preview');
    await page.waitForFunction(() => window.layerbotPackTest!.state().preview);
    const s = await packState();
    expect(s.restrictions?.locked).toEqual([{ layer: 'Bottom' }]);
    expect((await check()).verdict.passed).toBe(true);
    await page.click('#pack-back-to-editor');
    await page.waitForFunction(() => window.layerbotPackTest!.state().pack === null);
    // Export.
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#pe-export')]);
    expect(download.suggestedFilename()).toBe('office-deliveries.pack.json');
    const text = readFileSync((await download.path())!, 'utf8');
    const parsed = parsePack(text, 'office-deliveries.pack.json');
    if (!parsed.ok) throw new Error(JSON.stringify(parsed.problems));
    const pack = parsed.value;
    expect(pack.title).toBe('Office deliveries');
    expect(pack.author).toBe('A. Teacher');
    expect(pack.challenges).toHaveLength(1);
    const c = pack.challenges[0];
    expect(c.title).toBe('Deliver along the plan');
    expect(c.id).toBe('office');
    expect(c.locked).toEqual([{ layer: 'Bottom' }]);
    expect(c.toolbox).not.toContain('Loops');
    expect(c.toolbox).toContain('Logic');
    expect(c.hints).toEqual(['Follow the plan one goal at a time.']);
    expect(c.criteria.map((k) => k.kind)).toEqual(['reachGoals', 'withinTicks', 'noCrash', 'noError', 'variants']);
    expect(c.criteria[1]).toEqual({ kind: 'withinTicks', ticks: 900 });
    expect(c.world.name).toBe('Office');
    expect(c.starter.layers.map((l) => l.name)).toEqual(['Top', 'Middle', 'Bottom']);
  });

  test('a problem in the draft is shown before export, naming the challenge and field', async () => {
    await page.fill('#crit-within-ticks', '5000'); // beyond the tick limit (2000)
    await page.waitForSelector('#pe-problems.err');
    const text = await page.locator('#pe-problems').innerText();
    expect(text).toContain('challenge "office"');
    expect(text).toContain('$.challenges[0].criteria[1].ticks');
    expect(pageErrors).toEqual([]);
  });
});
