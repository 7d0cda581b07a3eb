/** The Create tools card: tool buttons, snap to grid, undo and redo. */
import type { Store } from '../app/store';
import { byId } from '../panels/dom';
import type { CreateState, Tool } from './selection';

export class ToolsPanel {
  constructor(
    private readonly create: CreateState,
    private readonly store: Store,
  ) {
    const tools = byId('tools');
    for (const b of tools.querySelectorAll<HTMLButtonElement>('[data-tool]')) {
      b.setAttribute('role', 'radio');
      b.addEventListener('click', () => create.setTool(b.dataset.tool as Tool));
    }
    const snap = byId<HTMLInputElement>('snap');
    const step = byId<HTMLSelectElement>('snap-step');
    snap.addEventListener('change', () => create.setSnap(snap.checked, Number(step.value)));
    step.addEventListener('change', () => create.setSnap(snap.checked, Number(step.value)));
    byId('btn-undo').addEventListener('click', () => store.undoWorld());
    byId('btn-redo').addEventListener('click', () => store.redoWorld());
    create.onChange.on(() => this.render());
    store.onWorld.on(() => this.render());
    this.render();
  }

  private render(): void {
    for (const b of byId('tools').querySelectorAll<HTMLButtonElement>('[data-tool]')) b.setAttribute('aria-checked', String(b.dataset.tool === this.create.tool));
    byId<HTMLButtonElement>('btn-undo').disabled = !this.store.undo.canUndo;
    byId<HTMLButtonElement>('btn-redo').disabled = !this.store.undo.canRedo;
  }
}
