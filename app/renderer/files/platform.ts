/**
 * File access for the page: the Electron preload API when present, the browser's file picker and
 * downloads otherwise. The rest of the app sees one interface.
 */
import type { FileKind, LayerbotDesktopApi, OpenedFile, SavedFile } from '../../main/api';

declare global {
  interface Window {
    /** Present only in the Electron app (app/main/preload.ts). */
    readonly layerbot?: LayerbotDesktopApi;
  }
}

export interface Platform {
  readonly desktop: boolean;
  openFile(kind: FileKind): Promise<OpenedFile | null>;
  openRecent(path: string): Promise<OpenedFile | null>;
  saveFile(kind: FileKind, path: string | null, suggestedName: string, text: string): Promise<SavedFile | null>;
  recentFiles(): Promise<readonly SavedFile[]>;
  readAutosave(): Promise<string | null>;
  writeAutosave(text: string): Promise<void>;
  /** Small local records by key (challenge-pack progress): the browser's local storage, also in Electron. */
  readStored(key: string): string | null;
  /** Returns false when the record could not be written (storage full or disabled). */
  writeStored(key: string, text: string): boolean;
}

function readStored(key: string): string | null {
  try {
    return localStorage.getItem(key);
  } catch {
    return null;
  }
}

function writeStored(key: string, text: string): boolean {
  try {
    localStorage.setItem(key, text);
    return true;
  } catch {
    return false;
  }
}

const AUTOSAVE_KEY = 'layerbot.autosave.v1';

const ACCEPT: Record<FileKind, string> = {
  world: '.json,.world.json,application/json',
  controller: '.json,.controller.json,application/json',
  any: '.json,application/json',
};

function pickFile(kind: FileKind): Promise<OpenedFile | null> {
  return new Promise((resolve) => {
    const input = document.createElement('input');
    input.type = 'file';
    input.accept = ACCEPT[kind];
    input.style.display = 'none';
    input.addEventListener('change', () => {
      const file = input.files?.[0];
      input.remove();
      if (!file) return resolve(null);
      void file.text().then((text) => resolve({ path: file.name, name: file.name, text }));
    });
    input.addEventListener('cancel', () => {
      input.remove();
      resolve(null);
    });
    document.body.appendChild(input);
    input.click();
  });
}

function download(name: string, text: string): SavedFile {
  const url = URL.createObjectURL(new Blob([text], { type: 'application/json' }));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
  return { path: name, name };
}

const browserPlatform: Platform = {
  desktop: false,
  openFile: pickFile,
  openRecent: () => Promise.resolve(null),
  saveFile: (_kind, _path, suggestedName, text) => Promise.resolve(download(suggestedName, text)),
  recentFiles: () => Promise.resolve([]),
  readAutosave: () => Promise.resolve(localStorage.getItem(AUTOSAVE_KEY)),
  writeAutosave: (text) => {
    try {
      localStorage.setItem(AUTOSAVE_KEY, text);
    } catch {
      // Storage full or disabled: autosave is a safety net, the user's files are unaffected.
    }
    return Promise.resolve();
  },
  readStored,
  writeStored,
};

function desktopPlatform(api: LayerbotDesktopApi): Platform {
  return {
    desktop: true,
    openFile: (kind) => api.openFile(kind),
    openRecent: (path) => api.openRecent(path),
    saveFile: (kind, path, name, text) => api.saveFile(kind, path, name, text),
    recentFiles: () => api.recentFiles(),
    readAutosave: () => api.readAutosave(),
    writeAutosave: (text) => api.writeAutosave(text),
    readStored,
    writeStored,
  };
}

/** The platform the page runs on. */
export function detectPlatform(): Platform {
  return window.layerbot?.version === 1 ? desktopPlatform(window.layerbot) : browserPlatform;
}
