/**
 * A tiny benchmark of the JS-Interpreter sandbox (not a test: run it by hand).
 *   npx esbuild tests/unit/sandbox/bench.ts --bundle --platform=node --outfile=/tmp/sandbox-bench.js && node /tmp/sandbox-bench.js
 */
import { Converter } from '../../../app/core/sandbox/convert';
import { createInterpreterSandbox } from '../../../app/core/sandbox/interpreter';
import { createInterpreter } from '../../../app/core/sandbox/setup';
import { deepFreeze } from '../../../app/core/values';

const fn = (name: string, params: string[], body: string) => ({ name, layer: 'L', params, source: `function ${name}(${params.join(', ')}) {\n'use strict';\n${body}\n}` });

function time(label: string, n: number, run: () => void): void {
  const t0 = process.hrtime.bigint();
  for (let i = 0; i < n; i++) run();
  const ms = Number(process.hrtime.bigint() - t0) / 1e6;
  console.log(`${label}: ${(ms / n).toFixed(4)} ms each, ${Math.round((n * 1000) / ms).toLocaleString('en-US')}/s`);
}

let t = process.hrtime.bigint();
const sandbox = createInterpreterSandbox([fn('add', ['a', 'b'], 'return a + b;'), fn('first', ['grid'], 'return grid[0][0][0];'), fn('loop', [], 'var s = 0; for (var i = 0; i < 1000; i++) s += i; return s;')]);
console.log(`create: ${Number(process.hrtime.bigint() - t) / 1e6} ms`);
time('trivial call add(1, 2)', 200_000, () => sandbox.call(0, [1, 2], 1000));
const r = sandbox.call(2, [], 1e6);
time(`loop call (${r.ok ? r.steps : '?'} steps)`, 2_000, () => sandbox.call(2, [], 1e6));

const grid = deepFreeze(Array.from({ length: 150 }, (_, y) => Array.from({ length: 150 }, (_, x) => [x, y, 0, 1, 2])));
const conv = new Converter(createInterpreter());
t = process.hrtime.bigint();
conv.toInput(grid);
console.log(`convert 150x150x5 input (first time): ${Number(process.hrtime.bigint() - t) / 1e6} ms`);
time('convert the same input again (cached)', 100_000, () => conv.toInput(grid));
const fresh = () => deepFreeze(Array.from({ length: 150 }, (_, y) => Array.from({ length: 150 }, (_, x) => [x, y, 0, 1, 2])));
const grids = Array.from({ length: 10 }, fresh);
let k = 0;
time('convert a new 150x150x5 input', 10, () => conv.toInput(grids[k++]));
const local = conv.toLocal(fresh());
time('convert a 150x150x5 result back to native', 10, () => conv.toNative(local));
time('call with the grid, cached', 50_000, () => sandbox.call(1, [grid], 1000));
