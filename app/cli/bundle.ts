/**
 * Worker threads run plain JavaScript files: their entries are bundled with esbuild into dist/ on
 * first use and whenever a source is newer than the bundle (the rule app/cli/bin.cjs applies to the
 * CLI itself), so they work straight from a fresh clone, from the bundled CLI and from Jest alike.
 */
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join } from 'node:path';
import type * as Esbuild from 'esbuild';

/**
 * The worker entries, by bundle name (dist/NAME.cjs), with the source folders whose changes make
 * a rebuild. The fast engine's workers get generated code from their parent and never load
 * Blockly; the grader's worker generates block code itself, so blocks/ is one of its sources.
 */
export const WORKER_ENTRIES = {
  'fast-worker': { entry: 'app/cli/fast-worker.ts', sources: ['app/core', 'app/cli'] },
  'bench-worker': { entry: 'app/cli/bench/bench-worker.ts', sources: ['app/core', 'app/cli'] },
  'grade-worker': { entry: 'app/cli/grade-worker.ts', sources: ['app/core', 'app/cli', 'blocks'] },
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
  const { entry, sources } = WORKER_ENTRIES[name];
  const outfile = join(root, 'dist', `${name}.cjs`);
  const dirs = sources.map((d) => join(root, d)).filter((d) => existsSync(d));
  const stale = !existsSync(outfile) || dirs.some((d) => newestMtime(d) > statSync(outfile).mtimeMs);
  if (stale) {
    // Loaded only when a build is needed: the bundled CLI does not carry esbuild.
    // eslint-disable-next-line @typescript-eslint/no-require-imports -- a lazy, optional dependency
    const esbuild = require('esbuild') as typeof Esbuild;
    esbuild.buildSync({
      entryPoints: [join(root, entry)],
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
