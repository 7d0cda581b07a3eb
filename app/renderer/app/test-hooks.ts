/**
 * A small read-only window into the app for the browser tests (tests/e2e) and for measuring:
 * where a world point is on screen, which tick is shown, the frame rate. It changes nothing.
 */
import type { App } from './app';

export interface LayerbotTestHooks {
  readonly ready: Promise<void>;
  /** A summary of what is on view. */
  state(): {
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
    ticksPerSecond: number;
  };
  /** Draws the world view once, now, and returns how long it took in milliseconds. */
  profile(): number;
  /** The page position (CSS pixels) of a world point in the world view. */
  toPage(x: number, y: number): { x: number; y: number };
}

declare global {
  interface Window {
    layerbotTest?: LayerbotTestHooks;
  }
}

export function exposeTestHooks(app: App, ready: Promise<void>): void {
  window.layerbotTest = {
    ready,
    state() {
      const frames = app.engine.frames;
      const f = frames[app.store.selectedTick];
      const create = app.store.mode === 'create';
      return {
        mode: app.store.mode,
        selectedTick: app.store.selectedTick,
        latestTick: frames.length - 1,
        running: app.engine.state.running,
        status: app.engine.state.status,
        hasController: app.engine.state.hasController,
        robot: create ? { ...app.store.world.robot } : f ? { x: f.x, y: f.y, heading: f.heading } : null,
        walls: app.store.world.walls.length,
        goals: app.store.world.goals.map((g) => g.name),
        plan: [...app.store.world.plan],
        worldName: app.store.world.name,
        fps: app.view.fps,
        ticksPerSecond: app.engine.state.ticksPerSecond,
      };
    },
    profile() {
      const t0 = performance.now();
      app.view.invalidate();
      app.view.renderNow();
      return performance.now() - t0;
    },
    toPage(x, y) {
      const r = app.view.app.canvas.getBoundingClientRect();
      const p = app.view.camera.toScreen(x, y);
      return { x: r.left + p.x, y: r.top + p.y };
    },
  };
}
