/**
 * The preload API the Electron renderer sees as `window.layerbot` (types only, shared by the
 * preload, the main process and the renderer). Every call is validated again in the main process.
 */

export type FileKind = 'world' | 'controller' | 'any';

/** A file the user chose or saved. */
export interface OpenedFile {
  readonly path: string;
  readonly name: string;
  readonly text: string;
}

export interface SavedFile {
  readonly path: string;
  readonly name: string;
}

export interface LayerbotDesktopApi {
  readonly version: 1;
  /** Shows the open dialog; null when cancelled. */
  openFile(kind: FileKind): Promise<OpenedFile | null>;
  /** Reads a file from the recent list (only paths the user opened or saved are allowed). */
  openRecent(path: string): Promise<OpenedFile | null>;
  /** Writes atomically to `path`, or asks where when `path` is null (Save As); null when cancelled. */
  saveFile(kind: FileKind, path: string | null, suggestedName: string, text: string): Promise<SavedFile | null>;
  recentFiles(): Promise<readonly SavedFile[]>;
  /** The autosaved work (in the app's autosave folder), or null. */
  readAutosave(): Promise<string | null>;
  writeAutosave(text: string): Promise<void>;
}

/** IPC channel names: one per API call. */
export const CHANNELS = {
  openFile: 'layerbot:open-file',
  openRecent: 'layerbot:open-recent',
  saveFile: 'layerbot:save-file',
  recentFiles: 'layerbot:recent-files',
  readAutosave: 'layerbot:read-autosave',
  writeAutosave: 'layerbot:write-autosave',
} as const;
