/** The dock's tabs (Arcs, Output, Errors): one visible panel at a time. */
export class DockTabs {
  current = 'arcs';

  constructor(private readonly root: HTMLElement) {
    for (const tab of root.querySelectorAll<HTMLButtonElement>('[data-dock]')) {
      tab.addEventListener('click', () => this.show(tab.dataset.dock as string));
    }
  }

  show(id: string): void {
    this.current = id;
    for (const tab of this.root.querySelectorAll<HTMLElement>('[data-dock]')) tab.setAttribute('aria-selected', String(tab.dataset.dock === id));
    for (const panel of this.root.querySelectorAll<HTMLElement>('[data-dock-panel]')) panel.hidden = panel.dataset.dockPanel !== id;
  }
}
