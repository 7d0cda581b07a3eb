/** Solve mode in the built app: open an example, step, run, scrub, and see each tick drawn. */
import type { Browser, Page } from 'playwright-core';
import { COLORS, launchApp, near, pixelAt, settle, state } from './support';

jest.setTimeout(60_000);

let browser: Browser;
let page: Page;
let pageErrors: string[];

beforeAll(async () => {
  let interactiveMs: number;
  ({ browser, page, pageErrors, interactiveMs } = await launchApp());
  // Reported, not asserted: timings vary with the machine (DESIGN.md section 9).
  console.log(`app interactive after ${interactiveMs} ms`);
});

afterAll(() => browser?.close());

async function openExample(kind: 'world' | 'controller', file: string): Promise<void> {
  await page.click('#file-button');
  await page.click(`#menu-example-${kind}s [data-example="${file}"]`);
}

test('starts with the office world and the basic controller, ready at tick 0', async () => {
  const s = await state(page);
  expect(s.worldName).toBe('Office');
  expect(s.hasController).toBe(true);
  expect(s.latestTick).toBe(0);
  expect(await page.locator('#status .pill').textContent()).toBe('Ready');
  // The robot is drawn at its start, a wall at its middle, and empty floor elsewhere.
  expect(near(await pixelAt(page, 0, 0), COLORS.robot)).toBe(true);
  expect(near(await pixelAt(page, 70, 10), COLORS.wall)).toBe(true);
  expect(near(await pixelAt(page, 47, 43), COLORS.background, 12)).toBe(true);
  expect(pageErrors).toEqual([]);
});

test('opens an example world from the File menu', async () => {
  await openExample('world', 'trap.world.json');
  await page.waitForFunction(() => window.layerbotTest!.state().worldName !== 'Office');
  const s = await state(page);
  expect(s.walls).toBe(9);
  expect(s.robot).toEqual({ x: -1, y: 0, heading: 90 });
  // The About tab comes forward with the example's description.
  await page.waitForSelector('#about-panel:not([hidden]) .about-name');
  expect(await page.locator('#about-panel .about-name').first().textContent()).toBe('Robot trap');
  expect(await page.locator('#about-panel .about-text').first().textContent()).toMatch(/\w+/);
  await page.click('#dock [data-dock="arcs"]');
});

test('Step computes one tick and the arc table shows it', async () => {
  await page.click('#btn-step');
  await page.keyboard.press('s');
  await page.waitForFunction(() => window.layerbotTest!.state().latestTick === 2);
  await page.waitForSelector('table.arcs[data-tick="2"]');
  const rows = await page.locator('table.arcs tbody tr').count();
  expect(rows).toBeGreaterThan(5);
  expect((await state(page)).selectedTick).toBe(2);
});

test('Run goes on until the robot crashes in the trap (tick 93), drawing the crash', async () => {
  await page.keyboard.press('End');
  // Full speed: the last stop of the speed slider.
  await page.locator('#speed').fill('10');
  await page.keyboard.press('Space');
  await page.waitForFunction(() => window.layerbotTest!.state().status === 'crashed', null, { timeout: 30_000 });
  await settle(page);
  const s = await state(page);
  expect(s.running).toBe(false);
  expect(s.latestTick).toBe(93);
  expect(await page.locator('#status .pill').textContent()).toBe('Crashed at tick 93');
});

test('scrubbing the timeline shows that tick in the world and the arc table', async () => {
  await page.locator('#tl-slider').fill('40');
  await page.waitForSelector('table.arcs[data-tick="40"]');
  const s = await state(page);
  expect(s.selectedTick).toBe(40);
  expect(await page.locator('#tl-number').inputValue()).toBe('40');
  expect(s.robot).not.toBeNull();
  const { x, y } = s.robot!;
  expect(near(await pixelAt(page, x, y), COLORS.robot)).toBe(true);
  // Back one tick with the keyboard.
  await page.keyboard.press('[');
  await page.waitForSelector('table.arcs[data-tick="39"]');
  const before = (await state(page)).robot!;
  expect(before).not.toEqual({ x, y, heading: s.robot!.heading });
  // Ticks after the selected one are not on the trail: the robot's later position is floor.
  const later = await page.evaluate(() => window.layerbotTest!.state());
  expect(later.latestTick).toBe(93);
});

test('Reset returns to tick 0 and clears the run', async () => {
  await page.keyboard.press('r');
  await page.waitForFunction(() => window.layerbotTest!.state().latestTick === 0);
  const s = await state(page);
  expect(s.status).toBe('ready');
  expect(s.robot).toEqual({ x: -1, y: 0, heading: 90 });
  expect(pageErrors).toEqual([]);
});
