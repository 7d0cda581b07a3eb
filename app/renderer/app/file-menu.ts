/** The File menu: a popup of actions, the examples and (in Electron) recent files. */
import { EXAMPLE_CONTROLLERS, EXAMPLE_WORLDS } from '../files/examples';
import type { Platform } from '../files/platform';
import { byId, el } from '../panels/dom';
import type { Documents } from './documents';

export class FileMenu {
  private readonly button = byId<HTMLButtonElement>('file-button');
  private readonly popup = byId('file-popup');

  constructor(
    private readonly docs: Documents,
    private readonly platform: Platform,
  ) {
    const actions: Record<string, () => unknown> = {
      'new-world': () => docs.newWorld(),
      open: () => docs.open(),
      'save-world': () => docs.saveWorld(false),
      'save-world-as': () => docs.saveWorld(true),
      'save-controller': () => docs.saveController(false),
      'save-controller-as': () => docs.saveController(true),
    };
    for (const b of this.popup.querySelectorAll<HTMLButtonElement>('[data-action]')) {
      b.addEventListener('click', () => {
        this.close();
        void actions[b.dataset.action as string]?.();
      });
    }
    const fill = (id: string, entries: typeof EXAMPLE_WORLDS): void => {
      byId(id).replaceChildren(
        ...entries.map((e) => {
          const b = el('button', undefined, e.title);
          b.setAttribute('role', 'menuitem');
          b.dataset.example = e.file;
          b.addEventListener('click', () => {
            this.close();
            void docs.openExample(e);
          });
          return b;
        }),
      );
    };
    fill('menu-example-worlds', EXAMPLE_WORLDS);
    fill('menu-example-controllers', EXAMPLE_CONTROLLERS);
    this.button.addEventListener('click', () => (this.popup.hidden ? this.open() : this.close()));
    document.addEventListener('pointerdown', (e) => {
      if (!this.popup.hidden && !byId('file-menu').contains(e.target as Node)) this.close();
    });
    this.popup.addEventListener('keydown', (e) => {
      if (e.key === 'Escape') {
        this.close();
        this.button.focus();
      }
    });
  }

  private async open(): Promise<void> {
    this.popup.hidden = false;
    this.button.setAttribute('aria-expanded', 'true');
    this.popup.querySelector<HTMLButtonElement>('button')?.focus();
    if (!this.platform.desktop) return;
    const recent = await this.platform.recentFiles();
    byId('menu-recent-wrap').hidden = recent.length === 0;
    byId('menu-recent').replaceChildren(
      ...recent.map((r) => {
        const b = el('button', undefined, r.name);
        b.title = r.path;
        b.addEventListener('click', () => {
          this.close();
          void this.docs.openRecent(r.path);
        });
        return b;
      }),
    );
  }

  close(): void {
    this.popup.hidden = true;
    this.button.setAttribute('aria-expanded', 'false');
  }
}
