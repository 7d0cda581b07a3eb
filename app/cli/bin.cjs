#!/usr/bin/env node
'use strict';
// The `layerbot` command. Its TypeScript sources are bundled with esbuild into dist/cli.cjs on
// first use and whenever a source changes, so `npx layerbot` works straight from a fresh clone.
const fs = require('node:fs');
const path = require('node:path');

const root = path.resolve(__dirname, '..', '..');
const bundle = path.join(root, 'dist', 'cli.cjs');
const sourceDirs = ['app/core', 'app/cli', 'blocks'].map((d) => path.join(root, d));

function newestMtime(dir) {
  let newest = 0;
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const p = path.join(dir, entry.name);
    if (entry.isDirectory()) newest = Math.max(newest, newestMtime(p));
    else if (/\.(ts|json)$/.test(entry.name)) newest = Math.max(newest, fs.statSync(p).mtimeMs);
  }
  return newest;
}

function isStale() {
  if (!fs.existsSync(bundle)) return true;
  const built = fs.statSync(bundle).mtimeMs;
  return sourceDirs.some((d) => fs.existsSync(d) && newestMtime(d) > built);
}

if (isStale()) {
  require('esbuild').buildSync({
    entryPoints: [path.join(root, 'app/cli/main.ts')],
    outfile: bundle,
    bundle: true,
    platform: 'node',
    format: 'cjs',
    target: 'node20',
    packages: 'external',
    sourcemap: 'inline',
    logLevel: 'error',
  });
}

require(bundle)
  .main(process.argv.slice(2))
  .then((code) => {
    process.exitCode = code;
  });
