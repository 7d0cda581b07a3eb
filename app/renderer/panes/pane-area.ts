/** The right-hand pane: a tab per ControllerPane, each mounted once into its own element. */
import type { ControllerError } from '../../core/session/types';
import type { ControllerPane, PaneHost, StepPoint } from './types';

export class PaneArea {
  private readonly panels = new Map<string, { pane: ControllerPane; el: HTMLElement; tab: HTMLButtonElement }>();
  private current: string | null = null;

  constructor(
    private readonly tabs: HTMLElement,
    private readonly body: HTMLElement,
    panes: readonly ControllerPane[],
    host: PaneHost,
  ) {
    for (const pane of panes) {
      const tab = document.createElement('button');
      tab.setAttribute('role', 'tab');
      tab.dataset.pane = pane.id;
      tab.textContent = pane.title;
      tab.addEventListener('click', () => this.show(pane.id));
      this.tabs.appendChild(tab);
      const el = document.createElement('div');
      el.className = 'pane-panel';
      el.dataset.paneId = pane.id;
      el.hidden = true;
      this.body.appendChild(el);
      this.panels.set(pane.id, { pane, el, tab });
    }
    for (const { pane, el } of this.panels.values()) {
      try {
        pane.mount(el, host);
      } catch (e) {
        // One broken pane must not take the app down: say so in its place.
        el.textContent = `This view could not start: ${e instanceof Error ? e.message : String(e)}`;
      }
    }
    if (panes.length) this.show(panes[0].id);
  }

  show(id: string): void {
    if (!this.panels.has(id) || id === this.current) return;
    const before = this.current ? this.panels.get(this.current) : undefined;
    if (before) {
      before.el.hidden = true;
      before.tab.setAttribute('aria-selected', 'false');
      before.pane.hidden?.();
    }
    const next = this.panels.get(id)!;
    next.el.hidden = false;
    next.tab.setAttribute('aria-selected', 'true');
    this.current = id;
    next.pane.shown?.();
  }

  /** Asks each pane to show the error's block; brings the first that does to the front. */
  revealError(error: ControllerError): boolean {
    for (const { pane } of this.panels.values()) {
      if (pane.revealError?.(error)) {
        this.show(pane.id);
        return true;
      }
    }
    return false;
  }

  /** Asks every pane to open a function; brings the first that shows it to the front. */
  openFunction(layer: string, fn: string): boolean {
    let shown: string | null = null;
    for (const { pane } of this.panels.values()) {
      if (pane.openFunction?.(layer, fn) && shown === null) shown = pane.id;
    }
    if (shown !== null) this.show(shown);
    return shown !== null;
  }

  /** Shows the debugger's position in every pane that can; brings the first to the front. */
  highlightStep(point: StepPoint | null): void {
    let shown = false;
    for (const { pane } of this.panels.values()) {
      if (pane.highlightStep?.(point) && !shown && point) {
        shown = true;
        this.show(pane.id);
      }
    }
  }
}
