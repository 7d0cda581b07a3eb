/**
 * Golden files of generated code: every function of every example controller, as the sandbox
 * receives it (the engine's wrapper around the generated body), in
 * tests/golden/generated/CONTROLLER/FUNCTION.js.golden (not .js, so lint leaves them alone). Run with UPDATE_GOLDEN=1 to rewrite them after
 * an intended change; review the diff like code.
 */
import { existsSync, mkdirSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { functionSource } from '../../app/core/controller/compile';
import { parseController } from '../../app/core/formats';
import { generateBody } from '../../blocks/generate';

const ROOT = join(__dirname, '..', '..');
const CONTROLLERS = join(ROOT, 'examples', 'controllers');
const GOLDEN = join(__dirname, 'generated');
const update = process.env.UPDATE_GOLDEN === '1';

const examples = readdirSync(CONTROLLERS)
  .filter((f) => f.endsWith('.controller.json'))
  .map((f) => f.replace(/\.controller\.json$/, ''));

describe.each(examples)('generated code of %s', (name) => {
  const file = join(CONTROLLERS, `${name}.controller.json`);
  const parsed = parseController(readFileSync(file, 'utf8'), file);
  if (!parsed.ok) throw new Error(JSON.stringify(parsed.problems));
  const functions = parsed.value.layers.flatMap((layer) => layer.functions.filter((fn) => fn.body.kind === 'blocks').map((fn) => ({ fn, layer })));

  test.each(functions.map((f) => [f.fn.name, f] as const))('%s', (fnName, { fn, layer }) => {
    const generated = generateBody(fn, layer);
    const source = `${functionSource(fn, layer, generated.code)}\n`;
    const golden = join(GOLDEN, name, `${fnName}.js.golden`);
    if (update) {
      mkdirSync(join(GOLDEN, name), { recursive: true });
      writeFileSync(golden, source);
    }
    expect(existsSync(golden)).toBe(true);
    expect(source).toBe(readFileSync(golden, 'utf8'));
    // The debug variant marks the same code with block ids, and nothing else differs.
    expect(generated.debugCode?.replace(/^\s*__block\('[^']*'\);\n/gm, '')).toBe(generated.code);
  });
});
