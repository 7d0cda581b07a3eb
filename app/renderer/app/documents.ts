/**
 * File actions: new world, open (a world or a controller, told apart by its format field), save,
 * save as, the bundled examples and the recent files. Problems in a file are shown, never thrown.
 */
import type { FileKind, OpenedFile } from '../../main/api';
import { detectFormat, formatProblems, parseController, parseWorld, serializeController, serializeWorld } from '../../core/formats';
import type { WorldSpec } from '../../core/world/world';
import type { ExampleEntry } from '../files/examples';
import type { Platform } from '../files/platform';
import { Emitter } from './emitter';
import type { Store } from './store';

/** The world a new document starts with: an empty room and the robot facing north. */
export function emptyWorld(): WorldSpec {
  return { name: 'Untitled world', walls: [], goals: [], plan: [], robot: { x: 0, y: 0, heading: 90 }, bounds: { minX: -10, minY: -10, maxX: 110, maxY: 60 } };
}

export class Documents {
  /** Takes pack files opened with Open… (set by the challenge packs, packs/index.ts). */
  onPackFile: ((file: OpenedFile) => boolean) | null = null;

  constructor(
    private readonly store: Store,
    private readonly platform: Platform,
  ) {}

  newWorld(): void {
    this.store.openWorld(emptyWorld(), { name: 'untitled.world.json', path: null });
    this.store.setMode('create');
    this.store.notice('New world: draw walls, place goals, then make a plan.');
  }

  async open(): Promise<void> {
    const file = await this.platform.openFile('any');
    if (file) this.openText(file);
  }

  async openRecent(path: string): Promise<void> {
    const file = await this.platform.openRecent(path);
    if (file) this.openText(file);
    else this.store.notice(`Could not open ${path}.`, 'error');
  }

  /** Opens a world or a controller from its text; returns true when it was read. */
  openText(file: OpenedFile): boolean {
    const kind = detectFormat(file.text) ?? (file.name.endsWith('.controller.json') ? 'controller' : file.name.endsWith('.pack.json') ? 'pack' : 'world');
    if (kind === 'pack' && this.onPackFile) return this.onPackFile(file);
    if (kind === 'controller') {
      const r = parseController(file.text, file.name);
      if (!r.ok) return this.problem(formatProblems(r.problems));
      this.store.openController(r.value, { name: file.name, path: file.path });
    } else if (kind === 'world') {
      const r = parseWorld(file.text, file.name);
      if (!r.ok) return this.problem(formatProblems(r.problems));
      this.store.openWorld(r.value, { name: file.name, path: file.path });
    } else {
      return this.problem(`${file.name} is a ${kind} file; open worlds or controllers here.`);
    }
    this.store.notice(`Opened ${file.name}.`);
    return true;
  }

  /** An example was opened from the menu (the app shows its description). */
  readonly onExampleOpened = new Emitter<ExampleEntry>();

  async openExample(entry: ExampleEntry): Promise<void> {
    this.openText({ path: '', name: entry.file, text: await entry.load() });
    this.onExampleOpened.emit(entry);
    const src = entry.file.endsWith('.controller.json') ? this.store.controllerSource : this.store.worldSource;
    // Examples have no path: Save asks where, so the bundled file is never overwritten.
    if (src) Object.assign(src, { path: null });
  }

  async saveWorld(as: boolean): Promise<void> {
    const src = this.store.worldSource;
    const name = src.name.endsWith('.world.json') ? src.name : `${slug(this.store.world.name)}.world.json`;
    await this.save('world', as ? null : src.path, name, serializeWorld(this.store.world), (saved) => {
      this.store.worldSource = saved;
    });
  }

  async saveController(as: boolean): Promise<void> {
    const c = this.store.controller;
    if (!c) return this.store.notice('There is no controller to save.', 'error');
    const src = this.store.controllerSource;
    const name = src?.name.endsWith('.controller.json') ? src.name : `${slug(c.name)}.controller.json`;
    let text: string;
    try {
      text = serializeController(c);
    } catch (e) {
      return this.store.notice(e instanceof Error ? e.message : String(e), 'error');
    }
    await this.save('controller', as ? null : (src?.path ?? null), name, text, (saved) => {
      this.store.controllerSource = saved;
    });
  }

  private async save(kind: FileKind, path: string | null, name: string, text: string, done: (s: { name: string; path: string | null }) => void): Promise<void> {
    try {
      const saved = await this.platform.saveFile(kind, path, name, text);
      if (!saved) return;
      done({ name: saved.name, path: this.platform.desktop ? saved.path : null });
      this.store.notice(this.platform.desktop ? `Saved ${saved.name}.` : `Downloaded ${saved.name}.`);
      this.store.onWorld.emit({ reason: 'document' });
    } catch (e) {
      this.store.notice(`Could not save: ${e instanceof Error ? e.message : String(e)}`, 'error');
    }
  }

  private problem(message: string): false {
    this.store.notice(message.split('\n')[0], 'error');
    return false;
  }
}

function slug(name: string): string {
  return name.trim().toLowerCase().replace(/[^a-z0-9]+/g, '-').replace(/^-|-$/g, '') || 'untitled';
}
