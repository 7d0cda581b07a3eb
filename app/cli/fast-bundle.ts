/**
 * Worker threads run plain JavaScript files: the fast engine's worker entries are bundled with
 * esbuild into dist/ on first use and whenever a source is newer than the bundle (the rule
 * app/cli/bin.cjs applies to the CLI), so they work straight from a fresh clone, from the bundled
 * CLI and from Jest alike.
 */
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join } from 'node:path';
import type * as Esbuild from 'esbuild';

/** The worker entries, by bundle name (dist/NAME.cjs), as paths from the repository root. */
export const WORKER_ENTRIES = {
  'fast-worker': 'app/cli/fast-worker.ts',
  'bench-worker': 'app/cli/bench/bench-worker.ts',
} as const;

export type WorkerName = keyof typeof WORKER_ENTRIES;

/** The repository root: the nearest folder above this file whose package.json is Layerbot's. */
export function repositoryRoot(from: string = __dirname): string {
  for (let dir = from; ; dir = dirname(dir)) {
    const pkg = join(dir, 'package.json');
    if (existsSync(pkg) && (JSON.parse(readFileSync(pkg, 'utf8')) as { name?: string }).name === 'layerbot') return dir;
    if (dirname(dir) === dir) throw new Error(`Cannot find Layerbot's package.json above ${from}.`);
  }
}

function newestMtime(dir: string): number {
  let newest = 0;
  for (const entry of readdirSync(dir, { withFileTypes: true })) {
    const p = join(dir, entry.name);
    if (entry.isDirectory()) newest = Math.max(newest, newestMtime(p));
    else if (/\.(ts|json)$/.test(entry.name)) newest = Math.max(newest, statSync(p).mtimeMs);
  }
  return newest;
}

/** The path of a worker's bundle, built first if it is missing or older than its sources. */
export function workerBundle(name: WorkerName): string {
  const root = repositoryRoot();
  const outfile = join(root, 'dist', `${name}.cjs`);
  const sources = ['app/core', 'app/cli'].map((d) => join(root, d)).filter((d) => existsSync(d));
  const stale = !existsSync(outfile) || sources.some((d) => newestMtime(d) > statSync(outfile).mtimeMs);
  if (stale) {
    // Loaded only when a build is needed: the bundled CLI does not carry esbuild.
    // eslint-disable-next-line @typescript-eslint/no-require-imports -- a lazy, optional dependency
    const esbuild = require('esbuild') as typeof Esbuild;
    esbuild.buildSync({
      entryPoints: [join(root, WORKER_ENTRIES[name])],
      outfile,
      bundle: true,
      platform: 'node',
      format: 'cjs',
      target: 'node20',
      packages: 'external',
      sourcemap: 'inline',
      logLevel: 'error',
    });
  }
  return outfile;
}
