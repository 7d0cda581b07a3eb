/** Helpers for the browser tests: launch Chromium on the served app, read state and pixels. */
import type { Browser, BrowserContext, Page } from 'playwright-core';
import { chromium } from 'playwright-core';

export const ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader', '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'];

export interface AppState {
  mode: string;
  selectedTick: number;
  latestTick: number;
  running: boolean;
  status: string;
  hasController: boolean;
  robot: { x: number; y: number; heading: number } | null;
  walls: number;
  goals: string[];
  plan: string[];
  worldName: string;
  fps: number;
  /** The world view's renderer: 'webgl' (with a GPU) or 'canvas'. */
  renderer: string;
  ticksPerSecond: number;
}

export async function launch(): Promise<{ browser: Browser; context: BrowserContext; page: Page }> {
  const executablePath = process.env.LAYERBOT_CHROMIUM ?? '/usr/bin/chromium';
  const browser = await chromium.launch({ executablePath, args: ARGS });
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  return { browser, context, page };
}

/** Opens the app and waits until it has started; `query` is added to the address (e.g. `?renderer=webgl`). */
export async function openApp(page: Page, query = ''): Promise<void> {
  const url = process.env.LAYERBOT_URL;
  if (!url) throw new Error('LAYERBOT_URL is not set: the browser tests must run through their global setup.');
  await page.goto(url + query);
  await page.waitForFunction(() => window.layerbotTest !== undefined);
  await page.evaluate(() => window.layerbotTest!.ready);
  await page.waitForFunction(() => window.layerbotTest!.state().latestTick >= 0);
}

/** A browser on the started app, with the page errors it reports and how long the app took to start. */
export interface LaunchedApp {
  browser: Browser;
  page: Page;
  /** Uncaught errors of the page, in order: a test ends by expecting none. */
  pageErrors: string[];
  /** From opening the address until the app was ready, in milliseconds (reported, never asserted). */
  interactiveMs: number;
}

/**
 * Launches Chromium and opens the app. `query` is added to the address; `beforeOpen` runs on the
 * page before it loads (to watch its requests).
 */
export async function launchApp(options: { query?: string; beforeOpen?: (page: Page) => void } = {}): Promise<LaunchedApp> {
  const { browser, page } = await launch();
  const pageErrors: string[] = [];
  page.on('pageerror', (e) => pageErrors.push(e.message));
  options.beforeOpen?.(page);
  const t0 = Date.now();
  await openApp(page, options.query);
  return { browser, page, pageErrors, interactiveMs: Date.now() - t0 };
}

export function state(page: Page): Promise<AppState> {
  return page.evaluate(() => window.layerbotTest!.state());
}

/** The page position of a world point. */
export function toPage(page: Page, x: number, y: number): Promise<{ x: number; y: number }> {
  return page.evaluate(([wx, wy]) => window.layerbotTest!.toPage(wx, wy), [x, y] as const);
}

/** Waits two animation frames, so the view shows the latest state. */
export async function settle(page: Page): Promise<void> {
  await page.evaluate(() => new Promise<void>((r) => requestAnimationFrame(() => requestAnimationFrame(() => r()))));
}

/** The colour [r, g, b] of the world view at a world point (read from its canvas). */
export async function pixelAt(page: Page, x: number, y: number): Promise<[number, number, number]> {
  await settle(page);
  return page.evaluate(([wx, wy]) => {
    const canvas = document.querySelector<HTMLCanvasElement>('canvas.world-canvas')!;
    const p = window.layerbotTest!.toPage(wx, wy);
    const r = canvas.getBoundingClientRect();
    const scale = canvas.width / r.width;
    const c = document.createElement('canvas');
    c.width = canvas.width;
    c.height = canvas.height;
    const ctx = c.getContext('2d')!;
    ctx.drawImage(canvas, 0, 0);
    const d = ctx.getImageData(Math.round((p.x - r.left) * scale), Math.round((p.y - r.top) * scale), 1, 1).data;
    return [d[0], d[1], d[2]] as [number, number, number];
  }, [x, y] as const);
}

/** True when two colours are within `tol` on every channel. */
export function near(a: readonly number[], hex: number, tol = 40): boolean {
  const b = [(hex >> 16) & 255, (hex >> 8) & 255, hex & 255];
  return a.every((v, i) => Math.abs(v - b[i]) <= tol);
}

export const COLORS = { robot: 0x4f46e5, wall: 0x2b3345, background: 0xfbfcfe, goal: 0x0e7490 };
