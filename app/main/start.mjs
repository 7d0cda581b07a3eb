#!/usr/bin/env node
/**
 * `npm start`: builds and opens the Electron app when its runtime is installed; otherwise says
 * so plainly and serves the web build at http://127.0.0.1:5173/ (PORT changes it) instead.
 * It never calls `require('electron')`, which would try to download the runtime.
 */
import { spawn } from 'node:child_process';
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

async function main() {
  const exe = electronBinary();
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
      'The Electron runtime is not installed, so Layerbot opens in your browser instead.',
      'To get the desktop app, on a machine with internet access run:  npx install-electron',
      '(or delete node_modules/electron and run npm install), then npm start again.',
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
