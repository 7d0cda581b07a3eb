#!/usr/bin/env node
/** Bundles the Electron main process and preload into dist/electron with esbuild (`electron` stays external). */
import { build } from 'esbuild';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '../..');

export async function buildElectron() {
  const common = { bundle: true, platform: 'node', format: 'cjs', target: 'node22', external: ['electron'], sourcemap: true, logLevel: 'warning' };
  await build({ ...common, entryPoints: [join(ROOT, 'app/main/main.ts')], outfile: join(ROOT, 'dist/electron/main.js') });
  // Sandboxed preloads run in a limited CommonJS context: one bundled file.
  await build({ ...common, entryPoints: [join(ROOT, 'app/main/preload.ts')], outfile: join(ROOT, 'dist/electron/preload.js') });
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) await buildElectron();
