/**
 * Automatic saving: the world and the controller are written to local storage (Electron: the
 * autosave folder) shortly after every change, and read back when the app starts, so a closed
 * window or a crash loses nothing.
 */
import type { ControllerSpec } from '../../core/controller/model';
import { parseController, parseWorld, serializeController, serializeWorld } from '../../core/formats';
import type { WorldSpec } from '../../core/world/world';
import type { DocumentSource, Mode } from '../app/store';
import type { Platform } from './platform';

export interface SavedWork {
  readonly world: WorldSpec;
  readonly worldSource: DocumentSource;
  readonly controller: ControllerSpec | null;
  readonly controllerSource: DocumentSource | null;
  readonly mode: Mode;
}

interface Envelope {
  readonly kind: 'layerbot-autosave';
  readonly version: 1;
  readonly world: string;
  readonly worldSource: DocumentSource;
  readonly controller: string | null;
  readonly controllerSource: DocumentSource | null;
  readonly mode: Mode;
}

const DELAY_MS = 400;

export class Autosave {
  private timer: ReturnType<typeof setTimeout> | null = null;
  private latest: (() => SavedWork) | null = null;

  constructor(private readonly platform: Platform) {
    // Write what is pending when the window goes away.
    window.addEventListener('pagehide', () => this.flush());
  }

  /** Schedules a save of the work `get` returns (read when the save happens). */
  schedule(get: () => SavedWork): void {
    this.latest = get;
    if (this.timer) clearTimeout(this.timer);
    this.timer = setTimeout(() => this.flush(), DELAY_MS);
  }

  flush(): void {
    if (this.timer) clearTimeout(this.timer);
    this.timer = null;
    const get = this.latest;
    if (!get) return;
    this.latest = null;
    const w = get();
    let controller: string | null = null;
    try {
      controller = w.controller ? serializeController(w.controller) : null;
    } catch {
      controller = null; // A controller the writer refuses is kept by the editor; the world still saves.
    }
    const env: Envelope = {
      kind: 'layerbot-autosave',
      version: 1,
      world: serializeWorld(w.world),
      worldSource: w.worldSource,
      controller,
      controllerSource: w.controllerSource,
      mode: w.mode,
    };
    void this.platform.writeAutosave(JSON.stringify(env));
  }

  /** The saved work, or null when there is none or it cannot be read. */
  async restore(): Promise<SavedWork | null> {
    let text: string | null;
    try {
      text = await this.platform.readAutosave();
    } catch {
      return null;
    }
    if (!text) return null;
    try {
      const env = JSON.parse(text) as Envelope;
      if (env.kind !== 'layerbot-autosave' || env.version !== 1) return null;
      const world = parseWorld(env.world, 'autosave.world.json');
      if (!world.ok) return null;
      const controller = env.controller ? parseController(env.controller, 'autosave.controller.json') : null;
      return {
        world: world.value,
        worldSource: env.worldSource,
        controller: controller && controller.ok ? controller.value : null,
        controllerSource: controller && controller.ok ? env.controllerSource : null,
        mode: env.mode === 'create' ? 'create' : 'solve',
      };
    } catch {
      return null;
    }
  }
}
