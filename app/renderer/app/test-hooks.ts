/**
 * A small read-only window into the app for the browser tests (tests/e2e) and for measuring:
 * where a world point is on screen, which tick is shown, the frame rate, what the controller editor
 * shows. It changes nothing, except `setRestrictions` (a challenge's locks, for the editor's tests).
 */
import type { ControllerSpec } from '../../core/controller/model';
import { editorFunctionBlockId, editorTestState } from '../editor/index';
import type { EditRestrictions } from '../panes/types';
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
    /** The world view's renderer: 'webgl' (with a GPU) or 'canvas'. */
    renderer: string;
    ticksPerSecond: number;
    /** The engine the Worker runs ticks with ('fast' or 'interpreter'; null until it has started). */
    engine: string | null;
  };
  /** Draws the world view once, now, and returns how long it took in milliseconds. */
  profile(): number;
  /** The page position (CSS pixels) of a world point in the world view. */
  toPage(x: number, y: number): { x: number; y: number };
  /** The controller editor: what its Blocks pane shows (view, open function, mode, toolbox...). */
  editor(): ReturnType<typeof editorTestState>;
  /** The controller editor's block id of a function (its block in the layers view). */
  editorBlockId(layer: string, fn: string): string | null;
  /** The controller as the app holds it (what the engine runs after the next load). */
  controller(): ControllerSpec | null;
  /** Sets a challenge's restrictions (locks, toolbox), as the packs view does. */
  setRestrictions(r: EditRestrictions | null): void;
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
        renderer: app.view.rendererName,
        ticksPerSecond: app.engine.state.ticksPerSecond,
        engine: app.engine.engine,
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
    editor: () => editorTestState(),
    editorBlockId: (layer, fn) => editorFunctionBlockId({ layer, fn }),
    controller: () => app.store.controller,
    setRestrictions: (r) => app.setRestrictions(r),
  };
}
