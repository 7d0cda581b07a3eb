/**
 * The renderer's entry: styles, then the app. The first start (nothing autosaved) opens the
 * textbook office world with the basic controller, so there is something to run at once.
 */
import './styles/app.css';
import { App } from './app/app';
import { EXAMPLE_CONTROLLERS, EXAMPLE_WORLDS } from './files/examples';
import { detectPlatform } from './files/platform';
import { exposeTestHooks } from './app/test-hooks';
import { installPacks } from './packs/index';
import { exposePackTestHooks } from './packs/test-hooks';

const platform = detectPlatform();
const app = new App(platform);

const ready = app.start(async () => {
  const world = EXAMPLE_WORLDS.find((e) => e.file === 'office.world.json') ?? EXAMPLE_WORLDS[0];
  const controller = EXAMPLE_CONTROLLERS.find((e) => e.file === 'basic.controller.json') ?? EXAMPLE_CONTROLLERS[0];
  if (world) await app.docs.openExample(world);
  if (controller) await app.docs.openExample(controller);
});

exposeTestHooks(app, ready);
exposePackTestHooks(app, installPacks(app, platform, ready));

ready.catch((e: unknown) => {
  // Startup failed (no WebGL, a broken build): say so on the page instead of a blank window.
  const box = document.createElement('div');
  box.className = 'empty-state';
  box.textContent = `Layerbot could not start: ${e instanceof Error ? e.message : String(e)}`;
  document.getElementById('world-host')?.appendChild(box);
});
