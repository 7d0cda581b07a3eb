/**
 * The world view draws the same picture with either renderer: WebGL (machines with a GPU) and
 * canvas (chosen where WebGL would run in software, as in this headless browser). Both are checked
 * by their pixels: the robot, a wall, the floor, and the trail after a few steps.
 */
import type { Browser, Page } from 'playwright-core';
import { COLORS, launchApp, near, pixelAt, state } from './support';

jest.setTimeout(90_000);

const TRAIL = 0x22a546;

describe.each(['webgl', 'canvas'])('the %s renderer', (renderer) => {
  let browser: Browser;
  let page: Page;
  let pageErrors: string[];

  beforeAll(async () => {
    ({ browser, page, pageErrors } = await launchApp({ query: `?renderer=${renderer}` }));
  });

  afterAll(() => browser?.close());

  test('draws the robot, the walls, the floor and the trail', async () => {
    expect((await state(page)).renderer).toBe(renderer);
    expect(near(await pixelAt(page, 0, 0), COLORS.robot)).toBe(true);
    expect(near(await pixelAt(page, 70, 10), COLORS.wall)).toBe(true);
    expect(near(await pixelAt(page, 47, 43), COLORS.background, 12)).toBe(true);
    for (let i = 0; i < 12; i++) await page.click('#btn-step');
    await page.waitForFunction(() => window.layerbotTest!.state().latestTick === 12);
    // Where the robot was at tick 5, a trail dot stands once the view shows tick 12.
    await page.locator('#tl-slider').fill('5');
    await page.waitForFunction(() => window.layerbotTest!.state().selectedTick === 5);
    const at5 = (await state(page)).robot!;
    await page.locator('#tl-slider').fill('12');
    await page.waitForFunction(() => window.layerbotTest!.state().selectedTick === 12);
    expect(near(await pixelAt(page, at5.x, at5.y), TRAIL, 60)).toBe(true);
    expect(pageErrors).toEqual([]);
  });

  test('keeps the trail when it grows past a chunk and when the timeline goes back', async () => {
    await page.locator('#tl-slider').fill('12');
    await page.click('#btn-run');
    await page.waitForFunction(() => window.layerbotTest!.state().status === 'done', null, { timeout: 60_000 });
    await page.locator('#tl-slider').fill('5');
    await page.waitForFunction(() => window.layerbotTest!.state().selectedTick === 5);
    const at5 = (await state(page)).robot!;
    for (const tick of [284, 100, 284]) {
      await page.locator('#tl-slider').fill(String(tick));
      await page.waitForFunction((t) => window.layerbotTest!.state().selectedTick === t, tick);
      expect(near(await pixelAt(page, at5.x, at5.y), TRAIL, 60)).toBe(true);
    }
    expect(pageErrors).toEqual([]);
  });
});
