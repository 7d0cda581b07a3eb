/** Create mode in the built app: draw a wall, place and name a goal, undo, and find the work after a reload. */
import type { Browser, Page } from 'playwright-core';
import { COLORS, launchApp, near, openApp, pixelAt, state, toPage } from './support';

jest.setTimeout(60_000);

let browser: Browser;
let page: Page;

beforeAll(async () => {
  ({ browser, page } = await launchApp());
  await page.click('#mode-switch [data-mode="create"]');
});

afterAll(() => browser?.close());

async function drag(from: [number, number], to: [number, number]): Promise<void> {
  const a = await toPage(page, ...from);
  const b = await toPage(page, ...to);
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  await page.mouse.move((a.x + b.x) / 2, (a.y + b.y) / 2, { steps: 4 });
  await page.mouse.move(b.x, b.y, { steps: 4 });
  await page.mouse.up();
}

test('draws a wall with the wall tool', async () => {
  const before = (await state(page)).walls;
  await page.click('[data-tool="wall"]');
  await drag([40, 30], [60, 30]);
  await page.waitForFunction((n) => window.layerbotTest!.state().walls === n + 1, before);
  await page.keyboard.press('Escape'); // Deselect: the selection is drawn over the wall.
  expect(near(await pixelAt(page, 50, 30), COLORS.wall)).toBe(true);
});

test('places a goal and names it in the inspector', async () => {
  await page.click('[data-tool="goal"]');
  const p = await toPage(page, 30, 45);
  await page.mouse.click(p.x, p.y);
  await page.waitForFunction(() => window.layerbotTest!.state().goals.length === 5);
  const name = page.locator('#inspector input[data-field="name"]');
  await name.fill('dock');
  await name.press('Enter');
  await page.waitForFunction(() => window.layerbotTest!.state().goals.includes('dock'));
  await page.click('#inspector button:has-text("Add to plan")');
  await page.waitForFunction(() => window.layerbotTest!.state().plan.at(-1) === 'dock');
});

test('undo and redo the last edit with the keyboard', async () => {
  await page.click('[data-tool="select"]');
  await page.keyboard.press('Control+z');
  await page.waitForFunction(() => !window.layerbotTest!.state().plan.includes('dock'));
  await page.keyboard.press('Control+y');
  await page.waitForFunction(() => window.layerbotTest!.state().plan.includes('dock'));
});

test('the work is restored after a reload', async () => {
  const before = await state(page);
  await page.waitForTimeout(600); // Autosave writes shortly after the last change.
  await page.reload();
  await openApp(page);
  const after = await state(page);
  expect(after.mode).toBe('create');
  expect(after.walls).toBe(before.walls);
  expect(after.goals).toContain('dock');
  expect(after.plan).toEqual(before.plan);
  expect(near(await pixelAt(page, 50, 30), COLORS.wall)).toBe(true);
});
