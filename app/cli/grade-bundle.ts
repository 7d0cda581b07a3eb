/**
 * The grader's worker entry, bundled with esbuild into dist/grade-worker.cjs on first use and
 * whenever a source is newer (the rule app/cli/bin.cjs and fast-bundle.ts apply), so worker
 * threads run plain JavaScript from a fresh clone, the bundled CLI and Jest alike. Unlike the fast
 * engine's workers, this one generates block code itself, so blocks/ counts as a source.
 */
import { existsSync, readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import type * as Esbuild from 'esbuild';
import { repositoryRoot } from './fast-bundle';

function newestMtime(dir: string): number {
  let newest = 0;
  for (const entry of readdirSync(dir, { withFileTypes: true })) {
    const p = join(dir, entry.name);
    if (entry.isDirectory()) newest = Math.max(newest, newestMtime(p));
    else if (/\.(ts|json)$/.test(entry.name)) newest = Math.max(newest, statSync(p).mtimeMs);
  }
  return newest;
}

/** The path of the grader's worker bundle, built first if it is missing or stale. */
export function gradeWorkerBundle(): string {
  const root = repositoryRoot();
  const outfile = join(root, 'dist', 'grade-worker.cjs');
  const sources = ['app/core', 'app/cli', 'blocks'].map((d) => join(root, d)).filter((d) => existsSync(d));
  const stale = !existsSync(outfile) || sources.some((d) => newestMtime(d) > statSync(outfile).mtimeMs);
  if (stale) {
    // Loaded only when a build is needed: the bundled CLI does not carry esbuild.
    // eslint-disable-next-line @typescript-eslint/no-require-imports -- a lazy, optional dependency
    const esbuild = require('esbuild') as typeof Esbuild;
    esbuild.buildSync({
      entryPoints: [join(root, 'app/cli/grade-worker.ts')],
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
