/**
 * The layerbot command as a user runs it: a child process, its output and its exit code.
 * Exit codes: 0 it ran, 1 a controller error, 2 bad input or usage.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { ROOT } from '../../support/examples';

const bin = join(ROOT, 'app', 'cli', 'bin.cjs');
const tmp = mkdtempSync(join(tmpdir(), 'layerbot-cli-'));
const office = join(ROOT, 'examples', 'worlds', 'office.world.json');
const basic = join(ROOT, 'examples', 'controllers', 'basic.controller.json');

function layerbot(...args: string[]) {
  const r = spawnSync(process.execPath, [bin, ...args], { encoding: 'utf8', timeout: 60_000 });
  return { code: r.status, out: r.stdout, err: r.stderr };
}

function file(name: string, content: unknown): string {
  const p = join(tmp, name);
  writeFileSync(p, typeof content === 'string' ? content : JSON.stringify(content, null, 2));
  return p;
}

/** The basic controller with one function's body replaced by text-mode code. */
function basicWith(functionName: string, code: string): string {
  const spec = JSON.parse(readFileSync(basic, 'utf8'));
  for (const layer of spec.layers) for (const f of layer.functions) if (f.name === functionName) f.body = { kind: 'text', code };
  return file(`${functionName}-${Math.abs(hash(code))}.controller.json`, spec);
}

function hash(s: string): number {
  let h = 0;
  for (const c of s) h = (h * 31 + c.charCodeAt(0)) | 0;
  return h;
}

jest.setTimeout(60_000);

describe('layerbot run', () => {
  test('prints the JSON summary with every goal reached', () => {
    const r = layerbot('run', basic, '--world', office, '--json');
    expect(r.code).toBe(0);
    const summary = JSON.parse(r.out);
    expect(summary).toMatchObject({ ticks: 284, crashed: false, crashTick: null, error: null });
    expect(summary.goals.map((g: { reachedTick: number }) => g.reachedTick)).toEqual([127, 170, 216, 284]);
    expect(summary.ticksPerSecond).toBeGreaterThan(0);
  });

  test('writes a CSV trace from tick 0', () => {
    const trace = join(tmp, 'office.csv');
    expect(layerbot('run', basic, '--world', office, '--trace', trace).code).toBe(0);
    const lines = readFileSync(trace, 'utf8').trim().split('\n');
    expect(lines[0]).toBe('tick,x,y,heading,whisker,crashed');
    expect(lines[1]).toBe('0,0,0,90,false,false');
    expect(lines).toHaveLength(286);
  });

  test('a crash is a result: exit code 0', () => {
    const r = layerbot('run', basic, '--world', join(ROOT, 'examples', 'worlds', 'trap.world.json'), '--json');
    expect(r.code).toBe(0);
    expect(JSON.parse(r.out)).toMatchObject({ crashed: true, crashTick: 93 });
  });

  test('an infinite loop is stopped and named: exit code 1', () => {
    const r = layerbot('run', basicWith('arrived', 'while (true) {}\nreturn false;'), '--world', office, '--json');
    expect(r.code).toBe(1);
    expect(JSON.parse(r.out).error).toMatch(/^Error in function "arrived" \(layer "Middle"\): .*steps/);
  });

  test('deep recursion is stopped and named: exit code 1', () => {
    const r = layerbot('run', basicWith('timer', 'function f(n) { return f(n + 1) + 1; }\nreturn f(0);'), '--world', office, '--json');
    expect(r.code).toBe(1);
    expect(JSON.parse(r.out).error).toMatch(/^Error in function "timer" \(layer "Top"\): /);
  });

  test('a huge list is stopped and named: exit code 1', () => {
    const r = layerbot('run', basicWith('todoChanged', 'var a = [];\nwhile (true) { a.push(a.length); }\nreturn false;'), '--world', office, '--json');
    expect(r.code).toBe(1);
    expect(JSON.parse(r.out).error).toMatch(/^Error in function "todoChanged" \(layer "Top"\): /);
  });

  test('changing an input is refused with advice to copy', () => {
    const r = layerbot('run', basicWith('todo', 'plan.push("x");\nreturn plan;'), '--world', office, '--json');
    expect(r.code).toBe(1);
    expect(JSON.parse(r.out).error).toMatch(/^Error in function "todo" \(layer "Top"\): .*copy/);
  });
});

describe('bad input: a clear message and exit code 2', () => {
  test.each([
    ['not JSON', () => file('broken.world.json', '{ "format": "layerbot-world", '), /broken\.world\.json/],
    ['a wrong type', () => file('typo.world.json', { ...JSON.parse(readFileSync(office, 'utf8')), robot: { x: 'zero', y: 0, heading: 90 } }), /\$\.robot\.x/],
    ['a missing field', () => file('nowalls.world.json', { ...JSON.parse(readFileSync(office, 'utf8')), walls: undefined }), /walls/],
  ])('world: %s', (_what, make, pattern) => {
    const r = layerbot('run', basic, '--world', make(), '--json');
    expect(r.code).toBe(2);
    expect(r.err).toMatch(pattern);
  });

  test('controller: an unknown arc source', () => {
    const spec = JSON.parse(readFileSync(basic, 'utf8'));
    spec.layers[1].functions[1].inputs[2].from = { kind: 'function', function: 'whiskerOnn' };
    const r = layerbot('run', file('unknown.controller.json', spec), '--world', office);
    expect(r.code).toBe(2);
    expect(r.err).toMatch(/\$\.layers\[1\]\.functions\[1\]\.inputs\[2\]\.from: .*"whiskerOnn".*Did you mean "whiskerOn"\?/);
  });

  test('controller: a cycle names its functions and suggests a previous-tick arc', () => {
    const spec = JSON.parse(readFileSync(basic, 'utf8'));
    const arrived = spec.layers[1].functions[0];
    arrived.inputs = arrived.inputs.map((i: { name: string }) => (i.name === 'previousTodo' ? { name: 'previousTodo', from: { kind: 'function', function: 'todo' } } : i));
    const r = layerbot('run', file('cycle.controller.json', spec), '--world', office);
    expect(r.code).toBe(2);
    expect(r.err).toMatch(/"todo".*"arrived"|"arrived".*"todo"/);
    expect(r.err).toContain('previous tick');
  });

  test('controller: duplicate input names', () => {
    const spec = JSON.parse(readFileSync(basic, 'utf8'));
    spec.layers[2].functions[0].inputs[1].name = 'walls';
    const r = layerbot('run', file('dup.controller.json', spec), '--world', office);
    expect(r.code).toBe(2);
    expect(r.err).toContain('two inputs named "walls"');
  });

  test('a missing file', () => {
    const r = layerbot('run', join(tmp, 'nope.controller.json'), '--world', office);
    expect(r.code).toBe(2);
    expect(r.err).toMatch(/nope\.controller\.json/);
  });

  test('usage errors', () => {
    expect(layerbot('run', basic).code).toBe(2);
    expect(layerbot('run', basic, '--world', office, '--ticks', 'many').code).toBe(2);
    expect(layerbot('frobnicate').code).toBe(2);
  });

  test('--help explains each command', () => {
    const r = layerbot('run', '--help');
    expect(r.code).toBe(0);
    expect(r.out).toContain('--trace');
  });
});

describe('layerbot check', () => {
  test('valid examples pass', () => {
    const r = layerbot('check', office, basic);
    expect(r.code).toBe(0);
    expect(r.out).toContain('All 2 files are valid.');
  });

  test('every problem of an invalid file is listed', () => {
    const bad = file('bad.world.json', { format: 'layerbot-world', version: 1, name: 'x', walls: [[[0, 0]]], goals: [], plan: ['home'], robot: { x: 0, y: 0, heading: 90 } });
    const r = layerbot('check', bad);
    expect(r.code).toBe(2);
    expect(r.err).toMatch(/\$\.walls\[0\]/);
    expect(r.err).toMatch(/home/);
  });
});
