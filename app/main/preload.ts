/**
 * The preload script: exposes `window.layerbot` (app/main/api.ts) through the context bridge.
 * The renderer gets these functions only; no Node, no ipcRenderer.
 */
import { contextBridge, ipcRenderer } from 'electron';
import type { FileKind, LayerbotDesktopApi } from './api';
import { CHANNELS } from './api';

const api: LayerbotDesktopApi = {
  version: 1,
  openFile: (kind: FileKind) => ipcRenderer.invoke(CHANNELS.openFile, kind),
  openRecent: (path: string) => ipcRenderer.invoke(CHANNELS.openRecent, path),
  saveFile: (kind: FileKind, path: string | null, suggestedName: string, text: string) => ipcRenderer.invoke(CHANNELS.saveFile, kind, path, suggestedName, text),
  recentFiles: () => ipcRenderer.invoke(CHANNELS.recentFiles),
  readAutosave: () => ipcRenderer.invoke(CHANNELS.readAutosave),
  writeAutosave: (text: string) => ipcRenderer.invoke(CHANNELS.writeAutosave, text),
};

contextBridge.exposeInMainWorld('layerbot', api);
