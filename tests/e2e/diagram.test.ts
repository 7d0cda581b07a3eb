/** The Diagram pane in the built app: bands and ovals, arc values at the selected tick, scrubbing, another example. */
import type { Browser, Page } from 'playwright-core';
import { launchApp, state } from './support';

jest.setTimeout(60_000);

let browser: Browser;
let page: Page;
let pageErrors: string[];

beforeAll(async () => {
  ({ browser, page, pageErrors } = await launchApp());
});

afterAll(() => browser?.close());

const BASIC: Record<string, string[]> = {
  Top: ['todo', 'todoChanged', 'timer'],
  Middle: ['arrived', 'steer'],
  Bottom: ['whiskerOn', 'lowLevelSteer', 'changePos'],
};

/** The page rectangles of the bands and the ovals on view. */
function geometry(): Promise<{ bands: { layer: string; top: number; bottom: number }[]; ovals: { fn: string; layer: string; cy: number; w: number }[] }> {
  return page.evaluate(() => {
    const bands = [...document.querySelectorAll<SVGGElement>('.dg-band')].map((g) => {
      const r = g.querySelector('rect')!.getBoundingClientRect();
      return { layer: g.dataset.layer!, top: r.top, bottom: r.bottom };
    });
    const ovals = [...document.querySelectorAll<SVGGElement>('.dg-fn')].map((g) => {
      const r = g.querySelector('.dg-fn-shape')!.getBoundingClientRect();
      return { fn: g.dataset.function!, layer: g.dataset.layer!, cy: r.top + r.height / 2, w: r.width };
    });
    return { bands, ovals };
  });
}

/** The value chip of a source (`steer`, `world.robotPos`, `previous.todo`), or null when hidden. */
function valueOf(source: string): Promise<string | null> {
  return page.evaluate((s) => {
    const g = document.querySelector<SVGGElement>(`.dg-value[data-source="${s}"]`);
    return g && g.style.display !== 'none' ? (g.querySelector('text')!.textContent ?? '') : null;
  }, source);
}

test('the Diagram tab draws every function of the basic controller as an oval in its band', async () => {
  await page.click('#pane-tabs [data-pane="diagram"]');
  await page.waitForSelector('.diagram .dg-fn');
  const { bands, ovals } = await geometry();
  expect(bands.map((b) => b.layer)).toEqual(['Top', 'Middle', 'Bottom']);
  for (const [layer, fns] of Object.entries(BASIC)) {
    const band = bands.find((b) => b.layer === layer)!;
    for (const fn of fns) {
      const o = ovals.find((x) => x.fn === fn);
      expect(o?.layer).toBe(layer);
      expect(o!.cy).toBeGreaterThan(band.top);
      expect(o!.cy).toBeLessThan(band.bottom);
      // Readable at the side pane's width: not shrunk to a speck.
      expect(o!.w).toBeGreaterThan(40);
    }
  }
  expect(ovals).toHaveLength(8);
  // Previous-tick arcs go through matching ports; the world inputs and the body sit below.
  expect(await page.locator('.dg-port-in[data-function="todo"]').count()).toBe(1);
  expect(await page.locator('.dg-port-out[data-function="todo"]').count()).toBe(1);
  expect(await page.locator('.dg-world[data-input="robotPos"]').count()).toBe(1);
  expect(await page.locator('.dg-world[data-input="tick"]').count()).toBe(0);
  expect(await page.locator('.dg-body').count()).toBe(1);
  expect(await page.locator('.dg-fn.dg-body-command[data-function="changePos"]').count()).toBe(1);
  // Tick 0: no function has run, so no values are shown.
  expect(await valueOf('world.robotPos')).toBeNull();
});

test('stepping shows the values on the arcs, and scrubbing the timeline changes them', async () => {
  for (let i = 0; i < 4; i++) await page.click('#btn-step');
  await page.waitForFunction(() => window.layerbotTest!.state().latestTick === 4);
  await page.waitForFunction(() => document.querySelector('.dg-tick')?.textContent === 'Tick 4');
  await page.waitForFunction(() => {
    const g = document.querySelector<SVGGElement>('.dg-value[data-source="world.robotPos"]');
    return !!g && g.style.display !== 'none';
  });
  const at4 = await valueOf('world.robotPos');
  expect(at4).toMatch(/^\[.*\]$/);
  expect(await valueOf('steer')).toMatch(/^"/);
  // The position changes every tick while the robot drives: emphasised as changed.
  expect(await page.locator('.dg-value.dg-changed[data-source="world.robotPos"]').count()).toBe(1);
  const tip = await page.locator('.dg-value[data-source="world.robotPos"] title').textContent();
  expect(tip).toContain('robotPos');

  await page.locator('#tl-slider').fill('2');
  await page.waitForFunction(() => document.querySelector('.dg-tick')?.textContent === 'Tick 2');
  await page.waitForFunction((before) => {
    const g = document.querySelector<SVGGElement>('.dg-value[data-source="world.robotPos"]');
    return !!g && g.style.display !== 'none' && g.querySelector('text')!.textContent !== before;
  }, at4);
  expect((await state(page)).selectedTick).toBe(2);
  expect(await valueOf('world.robotPos')).not.toBe(at4);

  await page.locator('#tl-slider').fill('0');
  await page.waitForFunction(() => document.querySelector('.dg-tick')?.textContent === 'Tick 0');
  await page.waitForFunction(() => document.querySelector<SVGGElement>('.dg-value[data-source="world.robotPos"]')!.style.display === 'none');
});

test('hovering a function brings its arcs forward; its context menu offers to step into it', async () => {
  await page.locator('#tl-slider').fill('3');
  await page.waitForFunction(() => document.querySelector('.dg-tick')?.textContent === 'Tick 3');
  await page.hover('.dg-fn[data-function="steer"]');
  expect(await page.locator('.diagram.dg-focusing').count()).toBe(1);
  expect(await page.locator('.dg-arc.dg-hot[data-target="steer"]').count()).toBe(5);
  await page.click('.dg-fn[data-function="steer"]', { button: 'right' });
  const items = await page.locator('.dg-menu .dg-menu-item').allTextContents();
  expect(items).toEqual(['Open blocks', 'Step into at tick 3', 'Fit to pane']);
  await page.keyboard.press('Escape');
  expect(await page.locator('.dg-menu').count()).toBe(0);
});

test('clicking a function selects it and opens the Blocks pane', async () => {
  await page.click('.dg-fn[data-function="arrived"]');
  await page.waitForFunction(() => document.querySelector('#pane-tabs [data-pane="blocks"]')?.getAttribute('aria-selected') === 'true');
  await page.click('#pane-tabs [data-pane="diagram"]');
  expect(await page.locator('.dg-fn.dg-selected[data-function="arrived"]').count()).toBe(1);
});

test('the wheel zooms and Fit brings the whole diagram back', async () => {
  const before = Number(await page.locator('.diagram').getAttribute('data-zoom'));
  const box = (await page.locator('.diagram').boundingBox())!;
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.wheel(0, -300);
  await page.waitForFunction((b) => Number(document.querySelector<HTMLElement>('.diagram')!.dataset.zoom) > b, before);
  await page.click('.dg-fit');
  expect(Number(await page.locator('.diagram').getAttribute('data-zoom'))).toBeCloseTo(before, 2);
});

test('the value-iteration example shows its four layers', async () => {
  await page.click('#file-button');
  await page.click('#menu-example-controllers [data-example="value-iteration.controller.json"]');
  await page.waitForFunction(() => document.querySelectorAll('.dg-band').length === 4);
  const { bands, ovals } = await geometry();
  expect(bands.map((b) => b.layer)).toEqual(['Top', 'Value iteration', 'Middle', 'Bottom']);
  const vi = ovals.filter((o) => o.layer === 'Value iteration').map((o) => o.fn).sort();
  expect(vi).toEqual(['chooseAction', 'currentState', 'getHasGoal', 'getHasWall', 'grid', 'valueIteration']);
  for (const o of ovals) {
    const band = bands.find((b) => b.layer === o.layer)!;
    expect(o.cy).toBeGreaterThan(band.top);
    expect(o.cy).toBeLessThan(band.bottom);
  }
  await page.click('#btn-step');
  await page.waitForFunction(() => window.layerbotTest!.state().latestTick === 1);
  await page.waitForFunction(() => {
    const g = document.querySelector<SVGGElement>('.dg-value[data-source="valueIteration"]');
    return !!g && g.style.display !== 'none';
  });
  expect(await valueOf('valueIteration')).toMatch(/grid|\[/);
  expect(pageErrors).toEqual([]);
});
