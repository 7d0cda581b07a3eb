/**
 * The controller editor in the built app: the basic controller's layers as blocks, opening a
 * function, editing a layer variable and seeing the robot go elsewhere, undo, text mode, and a
 * challenge's locks and toolbox.
 */
import type { Browser, Page } from 'playwright-core';
import { launchApp, settle, state } from './support';

jest.setTimeout(90_000);

let browser: Browser;
let page: Page;
let pageErrors: string[];

type EditorState = NonNullable<ReturnType<NonNullable<Window['layerbotTest']>['editor']>>;

const editor = (): Promise<EditorState> => page.evaluate(() => window.layerbotTest!.editor()!);

/** Waits for the engine to hold a fresh load (tick 0), then steps `n` ticks and returns the robot. */
async function robotAfter(n: number): Promise<{ x: number; y: number; heading: number }> {
  await page.waitForFunction(() => window.layerbotTest!.state().latestTick === 0 && window.layerbotTest!.state().hasController);
  for (let i = 1; i <= n; i++) {
    await page.click('#btn-step');
    await page.waitForFunction((t) => window.layerbotTest!.state().latestTick >= t, i);
  }
  await settle(page);
  return (await state(page)).robot!;
}

async function openFromJump(layer: string, fn: string): Promise<void> {
  await page.selectOption('.lbe-jump', { value: `${layer}\u0000${fn}` });
  await page.waitForFunction(([l, f]) => window.layerbotTest!.editor()?.opened?.layer === l && window.layerbotTest!.editor()?.opened?.fn === f, [layer, fn] as const);
}

async function backToController(): Promise<void> {
  await page.click('[data-crumb="controller"]');
  await page.waitForFunction(() => window.layerbotTest!.editor()?.view === 'controller');
}

beforeAll(async () => {
  ({ browser, page, pageErrors } = await launchApp());
});

afterAll(() => browser?.close());

test('the Blocks pane shows the basic controller as layer blocks, top to bottom', async () => {
  await page.click('#pane-tabs [data-pane="blocks"]');
  await page.waitForSelector('.lbe-ctrl-ws .blocklySvg');
  expect((await editor()).layers).toEqual(['Top', 'Middle', 'Bottom']);
  expect((await editor()).view).toBe('controller');
  // The layers and their functions are drawn as blocks.
  for (const name of ['Top', 'Middle', 'todo', 'arrived']) {
    await expect(page.locator('.lbe-ctrl-ws .blocklyEditableField', { hasText: new RegExp(`^${name}$`) }).first().isVisible()).resolves.toBe(true);
  }
  expect(await page.locator('.lbe-crumbs').textContent()).toContain('Basic controller');
  expect(pageErrors).toEqual([]);
});

test('double-clicking a function block opens its blocks; the breadcrumb goes back', async () => {
  const id = await page.evaluate(() => window.layerbotTest!.editorBlockId('Top', 'todo'));
  expect(id).not.toBeNull();
  const box = (await page.locator(`.lbe-ctrl-ws g[data-id="${id}"] > .blocklyPath`).first().boundingBox())!;
  // The first row starts with the "open" button, then the word "function" (not an editable field).
  await page.mouse.dblclick(box.x + 44, box.y + 9);
  await page.waitForFunction(() => window.layerbotTest!.editor()?.view === 'function');
  expect((await editor()).opened).toEqual({ layer: 'Top', fn: 'todo' });
  expect((await page.locator('.lbe-crumbs').textContent())?.replace(/\s+/g, ' ')).toContain('Controller›Top›todo');
  await page.waitForSelector('.lbe-body-ws .blocklyToolbox, .lbe-body-ws .blocklyToolboxDiv', { state: 'attached' });
  expect((await editor()).toolbox).toContain('Logic');
  await backToController();

  // The "open" button at the start of a function block opens it with one click.
  const timer = await page.evaluate(() => window.layerbotTest!.editorBlockId('Top', 'timer'));
  const tbox = (await page.locator(`.lbe-ctrl-ws g[data-id="${timer}"] > .blocklyPath`).first().boundingBox())!;
  await page.mouse.click(tbox.x + 14, tbox.y + 9);
  await page.waitForFunction(() => window.layerbotTest!.editor()?.opened?.fn === 'timer');
  await backToController();
});

test('changing a layer variable changes where the robot goes; Ctrl+Z undoes it', async () => {
  const before = await robotAfter(20);
  // STRAIGHT (layer Middle) is how far off the goal's direction the robot still goes straight.
  await page.locator('.lbe-ctrl-ws .blocklyEditableField', { hasText: /^11$/ }).first().click();
  const input = page.locator('.blocklyHtmlInput');
  await input.waitFor();
  await input.fill('200');
  await input.press('Enter');
  await page.waitForFunction(() => window.layerbotTest!.controller()?.layers[1].variables.find((v) => v.name === 'STRAIGHT')?.value === 200);
  const after = await robotAfter(20);
  expect(Math.hypot(after.x - before.x, after.y - before.y)).toBeGreaterThan(1);
  // With a wide "straight" band it never turns: it keeps its start heading.
  expect(after.heading).toBe(90);

  // Undo inside the workspace, from the keyboard.
  await page.locator('.lbe-ctrl-ws .blocklyMainBackground').click({ position: { x: 30, y: 30 }, force: true });
  await page.keyboard.press('Control+z');
  await page.waitForFunction(() => window.layerbotTest!.controller()?.layers[1].variables.find((v) => v.name === 'STRAIGHT')?.value === 11);
  const again = await robotAfter(20);
  expect(again).toEqual(before);
});

test('a function switches to JavaScript text, runs as written, and back to its blocks', async () => {
  await openFromJump('Bottom', 'lowLevelSteer');
  await page.click('.lbe-seg-btn[data-mode="text"]');
  await page.waitForFunction(() => window.layerbotTest!.editor()?.mode === 'text');
  const area = page.locator('.lbe-blocks .lbe-textarea');
  expect(await area.inputValue()).toContain('return');
  expect(await page.locator('.lbe-blocks .lbe-frame').first().textContent()).toContain('function lowLevelSteer(heading, steer) {');
  // A robot that never turns.
  await area.fill('return heading;');
  await page.waitForFunction(() => window.layerbotTest!.controller()?.layers[2].functions.find((f) => f.name === 'lowLevelSteer')?.body.kind === 'text');
  await page.waitForFunction(() => {
    const fn = window.layerbotTest!.controller()?.layers[2].functions.find((f) => f.name === 'lowLevelSteer');
    return fn?.body.kind === 'text' && fn.body.code === 'return heading;';
  });
  const robot = await robotAfter(10);
  expect(robot.heading).toBe(90);

  // The Code pane shows the same text, editable, under the header the engine adds.
  await page.click('#pane-tabs [data-pane="code"]');
  await page.waitForSelector('.lbe-codepane .lbe-textarea');
  expect(await page.locator('.lbe-codepane .lbe-picker').inputValue()).toBe('Bottom\u0000lowLevelSteer');
  expect(await page.locator('.lbe-codepane .lbe-textarea').inputValue()).toBe('return heading;');
  expect(await page.locator('.lbe-codepane .lbe-meta').textContent()).toContain('JavaScript text');

  // Back to blocks: asks first, then restores the blocks it had.
  await page.click('#pane-tabs [data-pane="blocks"]');
  await page.click('.lbe-seg-btn[data-mode="blocks"]');
  await page.locator('.lbe-dialog').getByRole('button', { name: 'Switch to blocks' }).click();
  await page.waitForFunction(() => window.layerbotTest!.editor()?.mode === 'blocks');
  await page.waitForFunction(() => window.layerbotTest!.controller()?.layers[2].functions.find((f) => f.name === 'lowLevelSteer')?.body.kind === 'blocks');
  await expect(page.locator('.lbe-body-ws .blocklyText', { hasText: 'remainder of' }).first().isVisible()).resolves.toBe(true);
  // The Code pane shows the generated code again.
  await page.click('#pane-tabs [data-pane="code"]');
  expect(await page.locator('.lbe-codepane .lbe-code-view').textContent()).toContain('function lowLevelSteer(heading, steer) {');
  await page.click('#pane-tabs [data-pane="blocks"]');
  await backToController();
});

test('a challenge locks a layer (visible, not editable) and limits the toolbox', async () => {
  // Unlocked, the text "left" in lowLevelSteer opens an editor when clicked.
  await openFromJump('Bottom', 'lowLevelSteer');
  const left = page.locator('.lbe-body-ws g.blocklyField', { hasText: /^left$/ }).first();
  await left.click();
  await page.locator('.blocklyHtmlInput').waitFor();
  await page.locator('.blocklyHtmlInput').press('Enter');
  await page.locator('.blocklyHtmlInput').waitFor({ state: 'hidden' });
  await backToController();

  await page.evaluate(() => window.layerbotTest!.setRestrictions({ locked: [{ layer: 'Bottom' }], toolbox: ['Logic', 'Math'] }));
  await openFromJump('Bottom', 'lowLevelSteer');
  let s = await editor();
  expect(s.readOnly).toBe(true);
  await expect(page.locator('.lbe-blocks .lbe-lock').isVisible()).resolves.toBe(true);
  expect(await page.locator('.lbe-seg-btn[data-mode="text"]').isDisabled()).toBe(true);
  // Clicking a number in the locked body opens no editor, and the controller stays as it was.
  const before = await page.evaluate(() => JSON.stringify(window.layerbotTest!.controller()));
  await left.click({ force: true });
  await settle(page);
  expect(await page.locator('.blocklyHtmlInput').count()).toBe(0);
  expect(await page.evaluate(() => JSON.stringify(window.layerbotTest!.controller()))).toBe(before);

  // An unlocked function is editable, with the challenge's two categories.
  await backToController();
  await openFromJump('Middle', 'arrived');
  s = await editor();
  expect(s.readOnly).toBe(false);
  expect(s.toolbox).toEqual(['Logic', 'Math']);
  await expect(page.locator('.lbe-blocks .lbe-lock').isVisible()).resolves.toBe(false);

  await page.evaluate(() => window.layerbotTest!.setRestrictions(null));
  expect((await editor()).toolbox.length).toBeGreaterThan(5);
  await backToController();
  expect(pageErrors).toEqual([]);
});
