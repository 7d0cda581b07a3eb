/**
 * What the page is working on: the world being built (a WorldSpec, edited only through `editSpec`
 * with undo and redo), the controller, the mode, the selected tick. Panels read it and subscribe;
 * changes go through its methods so every listener hears about them.
 */
import type { ControllerSpec } from '../../core/controller/model';
import type { WorldEdit } from '../../core/world/edits';
import { editSpec } from '../../core/world/edits';
import type { WorldSpec } from '../../core/world/world';
import { Emitter } from './emitter';
import { UndoStack } from './undo';

export type Mode = 'create' | 'solve';

/** Where a document came from, for the title and Save. */
export interface DocumentSource {
  readonly name: string;
  /** A path on disk (Electron) or null (an example, a browser upload, a new document). */
  readonly path: string | null;
}

export class Store {
  mode: Mode = 'solve';
  world: WorldSpec;
  worldSource: DocumentSource;
  controller: ControllerSpec | null = null;
  controllerSource: DocumentSource | null = null;
  /** The tick shown in the world view, the arc table and the output panel. */
  selectedTick = 0;
  /** While true the selection follows the newest tick (unset by scrubbing, set by Run and Reset). */
  follow = true;
  readonly undo = new UndoStack<WorldSpec>();

  readonly onMode = new Emitter<Mode>();
  /** The world spec changed: `edit` (undoable) or a new document. */
  readonly onWorld = new Emitter<{ readonly reason: 'edit' | 'undo' | 'document' }>();
  readonly onController = new Emitter<void>();
  readonly onSelect = new Emitter<number>();
  /** A message for the status line (file saved, edit refused, ...). */
  readonly onNotice = new Emitter<{ readonly text: string; readonly kind: 'info' | 'error' }>();

  constructor(world: WorldSpec) {
    this.world = world;
    this.worldSource = { name: `${world.name}.world.json`, path: null };
  }

  setMode(mode: Mode): void {
    if (mode === this.mode) return;
    this.mode = mode;
    this.onMode.emit(mode);
  }

  /** Applies a Create edit; a refused edit becomes a notice, never an exception. */
  editWorld(edit: WorldEdit): boolean {
    try {
      const next = editSpec(this.world, edit);
      this.undo.push(this.world);
      this.world = next;
      this.onWorld.emit({ reason: 'edit' });
      return true;
    } catch (e) {
      this.notice(e instanceof Error ? e.message : String(e), 'error');
      return false;
    }
  }

  /** Replaces the world's name or description (undoable). */
  renameWorld(name: string): void {
    this.undo.push(this.world);
    this.world = { ...this.world, name };
    this.onWorld.emit({ reason: 'edit' });
  }

  undoWorld(): void {
    const prev = this.undo.undo(this.world);
    if (prev) {
      this.world = prev;
      this.onWorld.emit({ reason: 'undo' });
    }
  }

  redoWorld(): void {
    const next = this.undo.redo(this.world);
    if (next) {
      this.world = next;
      this.onWorld.emit({ reason: 'undo' });
    }
  }

  openWorld(world: WorldSpec, source: DocumentSource): void {
    this.world = world;
    this.worldSource = source;
    this.undo.clear();
    this.onWorld.emit({ reason: 'document' });
  }

  openController(controller: ControllerSpec | null, source: DocumentSource | null): void {
    this.controller = controller;
    this.controllerSource = source;
    this.onController.emit();
  }

  /** Selects a tick; `follow` says whether the selection should then track the newest tick. */
  select(tick: number, follow = false): void {
    this.follow = follow;
    if (tick === this.selectedTick) return;
    this.selectedTick = tick;
    this.onSelect.emit(tick);
  }

  notice(text: string, kind: 'info' | 'error' = 'info'): void {
    this.onNotice.emit({ text, kind });
  }
}
