#!/usr/bin/env node
/**
 * `npm start`: builds and opens the Electron app. Electron's npm package no longer downloads its
 * runtime at install time, so the first start fetches it (the package's own installer); where
 * that cannot be done (offline, or a blocked host), it says so plainly and serves the web build at
 * http://127.0.0.1:5173/ (PORT changes it) instead.
 */
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { buildElectron } from './build.mjs';
import { buildWeb, serve, WEB_DIR } from './serve.mjs';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '../..');

/** The Electron executable, or null when the runtime binary was never downloaded. */
function electronBinary() {
  const pkg = join(ROOT, 'node_modules/electron');
  const pathFile = join(pkg, 'path.txt');
  if (!existsSync(pathFile)) return null;
  const exe = join(pkg, 'dist', readFileSync(pathFile, 'utf8').trim());
  return existsSync(exe) ? exe : null;
}

/** Runs Electron's own installer, which downloads the runtime; true when it is there afterwards. */
function installElectron() {
  const installer = join(ROOT, 'node_modules/electron/install.js');
  if (!existsSync(installer) || process.env.LAYERBOT_NO_DOWNLOAD) return false;
  console.log('Fetching the Electron runtime (first start only)…');
  const r = spawnSync(process.execPath, [installer], { stdio: ['ignore', 'ignore', 'pipe'], timeout: 300_000, encoding: 'utf8' });
  if (r.status !== 0) {
    const reason = (r.stderr ?? '').split('\n').find((l) => /Error|ENOTFOUND|EAI_AGAIN|ECONN|timed out/i.test(l));
    console.log(`Could not fetch it${reason ? ` (${reason.trim()})` : ''}.`);
  }
  return electronBinary() !== null;
}

async function main() {
  const exe = electronBinary() ?? (installElectron() ? electronBinary() : null);
  if (exe) {
    console.log('Building Layerbot…');
    buildWeb();
    await buildElectron();
    const child = spawn(exe, [join(ROOT, 'dist/electron/main.js')], { stdio: 'inherit' });
    child.on('exit', (code) => process.exit(code ?? 0));
    return;
  }
  console.log(
    [
      '',
      'The Electron runtime is not installed, so Layerbot opens in your browser instead.',
      'To get the desktop app, run npm start again on a machine that can reach Electron\'s download',
      'server (or run  npx install-electron  there). Everything else works the same in the browser.',
      '',
    ].join('\n'),
  );
  if (!existsSync(join(WEB_DIR, 'index.html'))) {
    console.log('Building the web app…');
    buildWeb();
  }
  const port = Number(process.env.PORT ?? 5173);
  const { url } = await serve(WEB_DIR, port);
  console.log(`Layerbot is running at ${url}  (open it in your browser; Ctrl+C stops it)`);
}

main().catch((e) => {
  console.error(e instanceof Error ? e.message : String(e));
  process.exit(1);
});
