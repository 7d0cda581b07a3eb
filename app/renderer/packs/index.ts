/**
 * Challenge packs in the app: installs the student's side (`PackSession`: the Challenges card,
 * the Challenge tab, Check) and connects the teacher's pack editor (a tab of the right-hand
 * pane), adds their File menu entries, and hands pack files opened with File › Open… to the
 * session. Call before `app.start` (the dock binds its tabs there); the pack open before a reload
 * is reopened once the app is ready.
 */
import './packs.css';
import type { App } from '../app/app';
import type { Platform } from '../files/platform';
import { byId, el } from '../panels/dom';
import { BUNDLED_PACKS } from './bundled';
import { packEditor } from './editor-pane';
import { PackSession } from './session';

export function installPacks(app: App, platform: Platform, ready: Promise<void>): PackSession {
  const session = new PackSession(app, platform);
  session.view.attach(byId('sidebar'), byId('dock'));
  addMenuItems(session);
  app.docs.onPackFile = (file) => session.openOpened(file);
  session.onBackToEditor = () => {
    session.close();
    packEditor.open();
  };
  void ready.then(async () => {
    packEditor.connect({
      world: () => app.store.world,
      controller: () => app.store.controller,
      load: (world, controller, id) => {
        app.store.openWorld(world, { name: `${id}.world.json`, path: null });
        app.store.openController(controller, { name: `${id}.controller.json`, path: null });
      },
      openPack: () => (session.preview ? null : session.pack),
      preview: (text, name) => {
        if (session.openText(text, name, null, false, true)) app.store.notice('Preview: this is what students see. Your progress here is not kept.');
      },
      save: async (name, text) => (await platform.saveFile('any', null, name, text))?.name ?? null,
      readStored: (key) => platform.readStored(key),
      writeStored: (key, text) => platform.writeStored(key, text),
      notice: (text, kind) => app.store.notice(text, kind),
    });
    await session.restore();
    session.render();
  });
  return session;
}

/** File menu: Open pack…, Pack editor…, and the example packs. */
function addMenuItems(session: PackSession): void {
  const popup = byId('file-popup');
  const item = (label: string, action: string, run: () => void): HTMLButtonElement => {
    const b = el('button', undefined, label);
    b.setAttribute('role', 'menuitem');
    // The File menu closes itself on any [data-action] item; the action is ours.
    b.dataset.action = action;
    b.addEventListener('click', run);
    return b;
  };
  const firstSep = popup.querySelector('.menu-sep');
  const items = [
    item('Open pack…', 'open-pack', () => void session.openFile()),
    item('Pack editor…', 'pack-editor', () => {
      packEditor.open();
    }),
  ];
  for (const b of items) popup.insertBefore(b, firstSep);
  const label = el('div', 'menu-label', 'Example packs');
  const group = el('div', 'menu-group');
  group.id = 'menu-example-packs';
  for (const p of BUNDLED_PACKS) {
    const b = item(p.file.replace(/\.pack\.json$/, ''), 'example-pack', () => void session.openBundled(p.file));
    b.dataset.example = p.file;
    group.appendChild(b);
  }
  const recent = byId('menu-recent-wrap');
  popup.insertBefore(label, recent);
  popup.insertBefore(group, recent);
}
