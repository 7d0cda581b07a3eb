/**
 * Keyboard shortcuts: Space run/stop, S or → step (→ moves the timeline when it is not at the
 * newest tick), ← [ ] Home End for the timeline, R reset, F fit, Ctrl+Z / Ctrl+Y undo and redo in
 * Create, Delete removes the selection, V W G B D pick Create tools, Ctrl+O open, Ctrl+S save.
 * Keys typed into fields, and keys inside the controller pane (Blockly has its own), are left alone.
 */
import type { Tool } from '../create/selection';
import { byId, isTyping } from '../panels/dom';
import type { App } from './app';

const TOOL_KEYS: Record<string, Tool> = { v: 'select', w: 'wall', g: 'goal', b: 'robot', d: 'delete' };

export function installKeys(app: App): void {
  document.addEventListener('keydown', (e) => {
    if (isTyping(e.target) || byId('side-pane').contains(e.target as Node)) return;
    const ctrl = e.ctrlKey || e.metaKey;
    const key = e.key.length === 1 ? e.key.toLowerCase() : e.key;
    const create = app.store.mode === 'create';
    let handled = true;
    if (ctrl) {
      if (key === 'z' && !e.shiftKey) app.store.undoWorld();
      else if (key === 'y' || (key === 'z' && e.shiftKey)) app.store.redoWorld();
      else if (key === 'o') void app.docs.open();
      else if (key === 's') void app.docs.saveWorld(e.shiftKey);
      else if (key === 'n' && e.altKey) app.docs.newWorld();
      else handled = false;
    } else if (e.altKey) {
      handled = false;
    } else if (key === ' ') {
      // A focused button would also "click" on Space: handle it once, here.
      app.toggleRun();
    } else if (key === 's') app.step();
    else if (key === 'ArrowRight' || key === ']') app.nudge(1, key === 'ArrowRight');
    else if (key === 'ArrowLeft' || key === '[') app.nudge(-1, false);
    else if (key === 'Home') app.store.select(0, false);
    else if (key === 'End') app.selectLast();
    else if (key === 'r') app.reset();
    else if (key === 'f') app.fit();
    else if (create && (key === 'Delete' || key === 'Backspace')) app.deleteSelection();
    else if (create && key === 'Escape') app.create.select(null);
    else if (create && TOOL_KEYS[key]) app.create.setTool(TOOL_KEYS[key]);
    else handled = false;
    if (handled) e.preventDefault();
  });
}
