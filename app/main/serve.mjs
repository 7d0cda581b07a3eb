#!/usr/bin/env node
/**
 * A tiny static server for the web build (dist/web) on 127.0.0.1. `npm run web` uses it; the
 * browser tests start it on a free port. Builds first when dist/web is missing (or --build).
 * Usage: node app/main/serve.mjs [--build] [--port N] (PORT also sets the port; 0 picks a free one).
 */
import { spawnSync } from 'node:child_process';
import { createReadStream, existsSync, statSync } from 'node:fs';
import { createServer } from 'node:http';
import { dirname, extname, join, normalize, resolve, sep } from 'node:path';
import { fileURLToPath, URL } from 'node:url';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
/** The web build; LAYERBOT_WEB_DIR points elsewhere (a second build beside the usual one). */
export const WEB_DIR = process.env.LAYERBOT_WEB_DIR ? resolve(process.env.LAYERBOT_WEB_DIR) : join(ROOT, 'dist/web');

const TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.map': 'application/json; charset=utf-8',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.gif': 'image/gif',
  '.cur': 'image/x-icon',
  '.ico': 'image/x-icon',
  '.mp3': 'audio/mpeg',
  '.wav': 'audio/wav',
  '.ogg': 'audio/ogg',
  '.woff2': 'font/woff2',
};

/**
 * The engine Worker's script (Vite names it assets/worker-HASH.js) is served with its own
 * Content-Security-Policy: the fast engine (SES) needs eval inside that Worker, and a dedicated
 * Worker takes its policy from its own response, not from the page, whose policy (index.html)
 * still forbids eval. The Worker may load only this app's scripts and reach nothing.
 */
export const ENGINE_WORKER = /^\/assets\/worker-[\w-]+\.js$/;
export const ENGINE_WORKER_CSP = "default-src 'none'; script-src 'self' 'unsafe-eval'; base-uri 'none'";

/** Builds the web app with Vite (a child process, so this file needs no dependencies). */
export function buildWeb() {
  const vite = join(ROOT, 'node_modules/vite/bin/vite.js');
  const r = spawnSync(process.execPath, [vite, 'build', '--logLevel', 'warn'], { cwd: ROOT, stdio: 'inherit' });
  if (r.status !== 0) throw new Error('The web build failed (see above).');
}

/** Serves `dir` on 127.0.0.1:`port`; resolves with the server and its URL. */
export function serve(dir = WEB_DIR, port = 5173) {
  const server = createServer((req, res) => {
    let path;
    try {
      path = decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname);
    } catch {
      res.writeHead(400).end('Bad request');
      return;
    }
    if (req.method !== 'GET' && req.method !== 'HEAD') {
      res.writeHead(405).end();
      return;
    }
    const file = normalize(join(dir, path.endsWith('/') ? path + 'index.html' : path));
    // Never serve anything outside the build folder.
    if (file !== dir && !file.startsWith(dir + sep)) {
      res.writeHead(403).end('Forbidden');
      return;
    }
    if (!existsSync(file) || !statSync(file).isFile()) {
      res.writeHead(404, { 'Content-Type': 'text/plain' }).end('Not found');
      return;
    }
    res.writeHead(200, {
      'Content-Type': TYPES[extname(file)] ?? 'application/octet-stream',
      'Cache-Control': 'no-cache',
      'X-Content-Type-Options': 'nosniff',
      ...(ENGINE_WORKER.test(path) ? { 'Content-Security-Policy': ENGINE_WORKER_CSP } : {}),
    });
    if (req.method === 'HEAD') res.end();
    else createReadStream(file).pipe(res);
  });
  return new Promise((resolveP, reject) => {
    server.once('error', reject);
    server.listen(port, '127.0.0.1', () => {
      const addr = server.address();
      resolveP({ server, url: `http://127.0.0.1:${typeof addr === 'object' && addr ? addr.port : port}/` });
    });
  });
}

async function main() {
  const args = process.argv.slice(2);
  const i = args.indexOf('--port');
  const port = Number(i >= 0 ? args[i + 1] : (process.env.PORT ?? 5173));
  if (!Number.isInteger(port) || port < 0 || port > 65535) {
    console.error(`Not a port number: ${i >= 0 ? args[i + 1] : process.env.PORT}`);
    process.exit(2);
  }
  if (args.includes('--build') || !existsSync(join(WEB_DIR, 'index.html'))) {
    console.log('Building the web app…');
    buildWeb();
  }
  try {
    const { url } = await serve(WEB_DIR, port);
    console.log(`Layerbot is running at ${url}  (Ctrl+C stops it)`);
  } catch (e) {
    console.error(e && e.code === 'EADDRINUSE' ? `Port ${port} is in use: set PORT to another one, e.g. PORT=5180 npm run web` : String(e));
    process.exit(1);
  }
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) void main();
