/**
 * A controller that fails while it runs: the run stops at that tick, the Errors panel names the
 * function, the layer and the tick, "Show block" opens the failing function in the Blocks pane,
 * and the student's controller is left as it was.
 */
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import type { Browser, Page } from 'playwright-core';
import { launchApp, state } from './support';

jest.setTimeout(90_000);

let browser: Browser;
let page: Page;
let pageErrors: string[];

/** The basic controller with WHISKER_LENGTH set to a text: whiskerOn's pointAt refuses it. */
function brokenController(): string {
  const spec = JSON.parse(readFileSync(join(__dirname, '../../examples/controllers/basic.controller.json'), 'utf8'));
  spec.name = 'Basic controller (broken whisker)';
  const bottom = spec.layers.find((l: { name: string }) => l.name === 'Bottom');
  bottom.variables = bottom.variables.map((v: { name: string; value: unknown }) => (v.name === 'WHISKER_LENGTH' ? { name: 'WHISKER_LENGTH', value: 'long' } : v));
  const dir = mkdtempSync(join(tmpdir(), 'layerbot-errors-'));
  const file = join(dir, 'broken.controller.json');
  writeFileSync(file, JSON.stringify(spec, null, 2));
  return file;
}

beforeAll(async () => {
  ({ browser, page, pageErrors } = await launchApp());
});

afterAll(() => browser?.close());

test('a failing function stops the run with its name, layer and tick, and Show block opens it', async () => {
  const chooser = page.waitForEvent('filechooser');
  await page.click('#file-button');
  await page.click('#file-menu [data-action="open"]');
  await (await chooser).setFiles(brokenController());
  await page.waitForFunction(() => window.layerbotTest!.controller()?.name === 'Basic controller (broken whisker)');
  await page.waitForFunction(() => window.layerbotTest!.state().hasController && window.layerbotTest!.state().latestTick === 0);

  await page.click('#btn-run');
  await page.waitForFunction(() => window.layerbotTest!.state().status === 'error', null, { timeout: 30_000 });
  const s = await state(page);
  // whiskerOn runs in every tick: the first one fails.
  expect(s.latestTick).toBe(1);
  expect(s.running).toBe(false);

  await page.click('#dock [data-dock="errors"]');
  const item = page.locator('#error-panel .err-item').first();
  await expect(item.locator('.where').textContent()).resolves.toContain('whiskerOn');
  await expect(item.locator('.meta').textContent()).resolves.toBe('layer Bottom · tick 1');
  await expect(item.locator('.msg').textContent()).resolves.toMatch(/pointAt: its input "length" should be a number/);

  await item.locator('button', { hasText: 'Show block' }).click();
  await page.waitForFunction(() => window.layerbotTest!.editor()?.opened?.fn === 'whiskerOn');
  expect(await page.locator('[data-pane="blocks"][aria-selected="true"]').count()).toBe(1);

  // Nothing the student built is lost: the controller still holds the broken value, ready to fix.
  const ctrl = await page.evaluate(() => window.layerbotTest!.controller());
  expect(ctrl?.layers.find((l) => l.name === 'Bottom')?.variables.find((v) => v.name === 'WHISKER_LENGTH')?.value).toBe('long');
  expect(pageErrors).toEqual([]);
});
