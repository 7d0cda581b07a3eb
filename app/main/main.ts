/**
 * The Electron main process, kept thin: one window loading the web build through a private
 * `app://` protocol (ES modules and the Worker load as from a web server; nothing remote), a
 * locked-down renderer, and the file dialogs, recent files and autosave behind validated IPC.
 */
import { app, BrowserWindow, dialog, ipcMain, net, protocol, session, shell } from 'electron';
import type { IpcMainInvokeEvent } from 'electron';
import { promises as fs } from 'node:fs';
import { basename, extname, join, normalize, sep } from 'node:path';
import { pathToFileURL } from 'node:url';
import type { FileKind, OpenedFile, SavedFile } from './api';
import { CHANNELS } from './api';
import { RecentFiles, writeAtomic } from './files';
import { isFileName, isKind, isPath, isText, MAX_TEXT } from './ipc-validate';

const WEB_DIR = join(__dirname, '../web');
const CSP =
  "default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data: blob:; font-src 'self' data:; " +
  "media-src 'self' data: blob:; worker-src 'self' blob:; connect-src 'self' blob: data:; object-src 'none'; base-uri 'none'; form-action 'none'; frame-src 'none'";

/**
 * The engine Worker's own policy: the fast engine (SES) needs eval inside that Worker only; the
 * page's policy above still forbids it (a dedicated Worker takes the policy of its own response).
 * Keep in step with serve.mjs.
 */
const ENGINE_WORKER = /^\/assets\/worker-[\w-]+\.js$/;
const ENGINE_WORKER_CSP = "default-src 'none'; script-src 'self' 'unsafe-eval'; base-uri 'none'";

protocol.registerSchemesAsPrivileged([{ scheme: 'app', privileges: { standard: true, secure: true, supportFetchAPI: true } }]);

const FILTERS: Record<FileKind, Electron.FileFilter[]> = {
  world: [{ name: 'Layerbot worlds', extensions: ['json'] }],
  controller: [{ name: 'Layerbot controllers', extensions: ['json'] }],
  any: [{ name: 'Layerbot files', extensions: ['json'] }],
};

let recent: RecentFiles;
let autosaveFile: string;
let mainWindow: BrowserWindow | null = null;

/** Only the app's own window may call the API. */
function fromApp(e: IpcMainInvokeEvent): boolean {
  return e.senderFrame?.url.startsWith('app://layerbot/') === true;
}

async function readFileChecked(path: string): Promise<OpenedFile> {
  const stat = await fs.stat(path);
  if (stat.size > MAX_TEXT) throw new Error(`${basename(path)} is too large to be a Layerbot file.`);
  const text = await fs.readFile(path, 'utf8');
  await recent.add(path);
  return { path, name: basename(path), text };
}

function handle(channel: string, fn: (...args: unknown[]) => Promise<unknown>): void {
  ipcMain.handle(channel, async (e, ...args: unknown[]) => {
    if (!fromApp(e)) throw new Error('Refused: not the Layerbot window.');
    return fn(...args);
  });
}

function registerIpc(): void {
  handle(CHANNELS.openFile, async (kind) => {
    if (!isKind(kind)) throw new Error('openFile: bad kind');
    const r = await dialog.showOpenDialog(mainWindow!, { properties: ['openFile'], filters: FILTERS[kind] });
    return r.canceled || !r.filePaths[0] ? null : readFileChecked(r.filePaths[0]);
  });
  handle(CHANNELS.openRecent, async (path) => {
    // Only files the user chose before: the renderer cannot read arbitrary paths.
    if (!isPath(path) || !(await recent.has(path))) throw new Error('openRecent: not a recent file');
    return readFileChecked(path);
  });
  handle(CHANNELS.saveFile, async (kind, path, suggestedName, text): Promise<SavedFile | null> => {
    if (!isKind(kind) || !(path === null || isPath(path)) || !isFileName(suggestedName) || !isText(text)) throw new Error('saveFile: bad arguments');
    let target = path;
    if (target !== null && !(await recent.has(target))) target = null; // Unknown path: ask.
    if (target === null) {
      const r = await dialog.showSaveDialog(mainWindow!, { defaultPath: suggestedName, filters: FILTERS[kind] });
      if (r.canceled || !r.filePath) return null;
      target = extname(r.filePath) ? r.filePath : `${r.filePath}.json`;
    }
    await writeAtomic(target, text);
    await recent.add(target);
    return { path: target, name: basename(target) };
  });
  handle(CHANNELS.recentFiles, async () => (await recent.all()).map((p) => ({ path: p, name: basename(p) })));
  handle(CHANNELS.readAutosave, async () => {
    try {
      return await fs.readFile(autosaveFile, 'utf8');
    } catch {
      return null;
    }
  });
  handle(CHANNELS.writeAutosave, async (text) => {
    if (!isText(text)) throw new Error('writeAutosave: bad text');
    await fs.mkdir(join(app.getPath('userData'), 'autosave'), { recursive: true });
    await writeAtomic(autosaveFile, text);
  });
}

/** Serves dist/web under app://layerbot/, refusing anything outside it. */
function registerProtocol(): void {
  protocol.handle('app', async (request) => {
    const url = new URL(request.url);
    const file = normalize(join(WEB_DIR, decodeURIComponent(url.pathname === '/' ? '/index.html' : url.pathname)));
    if (url.host !== 'layerbot' || !file.startsWith(WEB_DIR + sep)) return new Response('Forbidden', { status: 403 });
    const response = await net.fetch(pathToFileURL(file).toString());
    const headers = new Headers(response.headers);
    headers.set('Content-Security-Policy', ENGINE_WORKER.test(url.pathname) ? ENGINE_WORKER_CSP : CSP);
    return new Response(response.body, { status: response.status, headers });
  });
}

function createWindow(): void {
  mainWindow = new BrowserWindow({
    width: 1400,
    height: 880,
    minWidth: 1024,
    minHeight: 640,
    title: 'Layerbot',
    backgroundColor: '#eef1f6',
    webPreferences: {
      preload: join(__dirname, 'preload.js'),
      contextIsolation: true,
      nodeIntegration: false,
      sandbox: true,
      webSecurity: true,
      spellcheck: false,
    },
  });
  const wc = mainWindow.webContents;
  // No navigation away from the app and no new windows; links open in the system browser.
  wc.on('will-navigate', (e, url) => {
    if (!url.startsWith('app://layerbot/')) e.preventDefault();
  });
  wc.setWindowOpenHandler(({ url }) => {
    if (url.startsWith('https://')) void shell.openExternal(url);
    return { action: 'deny' };
  });
  void mainWindow.loadURL('app://layerbot/index.html');
}

app.enableSandbox();
void app.whenReady().then(() => {
  recent = new RecentFiles(join(app.getPath('userData'), 'recent-files.json'));
  autosaveFile = join(app.getPath('userData'), 'autosave', 'work.json');
  // Deny every permission request (camera, notifications, ...): the app needs none.
  session.defaultSession.setPermissionRequestHandler((_wc, _perm, cb) => cb(false));
  registerProtocol();
  registerIpc();
  createWindow();
  app.on('activate', () => {
    if (BrowserWindow.getAllWindows().length === 0) createWindow();
  });
});

app.on('window-all-closed', () => {
  if (process.platform !== 'darwin') app.quit();
});
