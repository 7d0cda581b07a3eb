/**
 * The Debugger tab in the built app: replay a function at a selected tick block by block, see its
 * variables, and get the value the run recorded.
 */
import type { Browser, Page } from 'playwright-core';
import { launchApp } from './support';

jest.setTimeout(60_000);

let browser: Browser;
let page: Page;
let pageErrors: string[];

beforeAll(async () => {
  ({ browser, page, pageErrors } = await launchApp());
});

afterAll(() => browser?.close());

const panel = '#debugger-panel';
const block = () => page.locator(panel).getAttribute('data-block');
const waitState = (state: string) => page.waitForSelector(`${panel}[data-state="${state}"]`);

/** Waits until the current block is not `before`, and returns it. */
async function nextBlock(before: string | null): Promise<string> {
  await page.waitForFunction(([sel, b]) => {
    const el = document.querySelector<HTMLElement>(sel as string)!;
    return el.dataset.state === 'paused' && el.dataset.block !== b;
  }, [panel, before] as const);
  return (await block()) as string;
}

/** The arc table's value on the arc from `from` at the tick shown. */
async function arcValueFrom(from: string): Promise<string> {
  const row = page.locator('table.arcs tbody tr').filter({ has: page.locator('td.from', { hasText: new RegExp(`^${from}$`) }) }).first();
  return (await row.locator('td.value').textContent()) as string;
}

test('steps the basic controller, selects tick 3, and steps into steer block by block', async () => {
  for (let i = 0; i < 4; i++) await page.click('#btn-step');
  await page.waitForFunction(() => window.layerbotTest!.state().latestTick === 4);
  await page.locator('#tl-slider').fill('3');
  await page.waitForSelector('table.arcs[data-tick="3"]');
  const recorded = await arcValueFrom('steer');

  await page.click('#dock [data-dock="debugger"]');
  await page.selectOption(`${panel} select.dbg-picker`, { label: 'steer  (Middle)' });
  await page.click(`${panel} .dbg-start`);
  const first = await nextBlock(null);
  expect(first).toBe('steer.4');
  await expect(page.locator(`${panel} .dbg-title`).textContent()).resolves.toContain('tick 3');
  // The current block's line is highlighted in the code.
  await expect(page.locator(`${panel} .dbg-code li.current`).textContent()).resolves.toContain('if (whisker)');
  // Inputs and layer variables are listed with their values; block variables are not set yet.
  const heading = await page.locator('table.arcs tbody tr').filter({ has: page.locator('td.to', { hasText: /^steer$/ }) }).filter({ has: page.locator('td.input', { hasText: /^heading$/ }) }).locator('td.value').textContent();
  await expect(page.locator(`${panel} tr[data-name="heading"] td.value`).textContent()).resolves.toBe(heading);
  await expect(page.locator(`${panel} tr[data-name="STRAIGHT"] td.value`).textContent()).resolves.toBe('11');
  await expect(page.locator(`${panel} tr[data-name="goal"] td.value`).textContent()).resolves.toBe('not set yet');

  const seen = [first];
  await page.click(`${panel} button[data-step="block"]`);
  seen.push(await nextBlock(seen[seen.length - 1]));
  await page.click(`${panel} button[data-step="block"]`);
  seen.push(await nextBlock(seen[seen.length - 1]));
  // F10 steps too.
  await page.keyboard.press('F10');
  seen.push(await nextBlock(seen[seen.length - 1]));
  expect(seen).toEqual(['steer.4', 'steer.9', 'steer.15', 'steer.21']);
  // `goal` was set by steer.9, `dx` by steer.15.
  await expect(page.locator(`${panel} tr[data-name="goal"] td.value`).textContent()).resolves.toMatch(/^\[-?\d/);
  await expect(page.locator(`${panel} tr[data-name="dx"] td.value`).textContent()).resolves.toMatch(/^-?\d/);

  await page.click(`${panel} button[data-step="end"]`);
  await waitState('done');
  const result = await page.locator(`${panel} .dbg-value`).textContent();
  expect(result).toBe(recorded);
  await expect(page.locator(`${panel} .dbg-compare`).getAttribute('data-same')).resolves.toBe('true');
  expect(pageErrors).toEqual([]);
});

test('Restart goes back to the first block; Esc closes the replay', async () => {
  await page.click(`${panel} button:has-text("Restart")`);
  expect(await nextBlock('done')).toBe('steer.4');
  await page.keyboard.press('Escape');
  await waitState('idle');
});

test('the arc table steps into a function at the tick it shows', async () => {
  await page.click('#dock [data-dock="arcs"]');
  await page.click('table.arcs[data-tick="3"] button[data-step-into="lowLevelSteer"]');
  await nextBlock(null);
  await expect(page.locator(`${panel} .dbg-title`).textContent()).resolves.toMatch(/lowLevelSteer.*tick 3/);
  await page.keyboard.press('F8');
  await waitState('done');
  await expect(page.locator(`${panel} .dbg-compare`).getAttribute('data-same')).resolves.toBe('true');
  expect(pageErrors).toEqual([]);
});
