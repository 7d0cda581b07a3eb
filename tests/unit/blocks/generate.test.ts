/** The block generator: local variables, printing, reserved words, random blocks, errors. */
import type { FunctionSpec, LayerSpec } from '../../../app/core/controller/model';
import { BodyBuilder, emptyBody } from '../../../blocks/build';
import { generateBody } from '../../../blocks/generate';
import { API, RESERVED_NAMES } from '../../../app/core/sandbox/api';
import { compileController } from '../../../app/core/controller/compile';
import { Session } from '../../../app/core/session/session';
import { createPlainSandbox } from '../../../app/cli/bench/plain-sandbox';
import { controller, forward, layer, world } from '../../support/controllers';
import type { JsonValue } from '../../../app/core/values';

const fnOf = (name: string, blocks: JsonValue, inputs: string[] = [], output: FunctionSpec['output'] = 'any'): FunctionSpec => ({
  name,
  output,
  inputs: inputs.map((i) => ({ name: i, from: { kind: 'world', input: 'tick' } })),
  body: { kind: 'blocks', blocks },
});
const layerOf = (variables: Record<string, JsonValue> = {}): LayerSpec => ({
  name: 'L',
  variables: Object.entries(variables).map(([name, value]) => ({ name, value })),
  randomSources: [],
  functions: [],
});

describe('generateBody', () => {
  test('block variables are declared with var inside the body: local to the function', () => {
    const b = new BodyBuilder('t');
    const body = b.body([b.set('x', b.num(1)), b.change('x', b.num(2))], b.get('x'));
    const code = generateBody(fnOf('f', body), layerOf()).code;
    expect(code.split('\n')[0]).toBe('var x;');
    // Two functions using the same variable name do not share it.
    const c = controller([layer('L', [fnOf('f', body, [], 'number'), fnOf('g', body, [], 'number'), forward()])]);
    const s = new Session(world, c, { sandbox: createPlainSandbox, generateBody });
    s.run(2);
    expect(s.history.at(2).outputs.slice(0, 2)).toEqual([3, 3]);
  });

  test('inputs and layer variables are read by their plain names', () => {
    const b = new BodyBuilder('t');
    const code = generateBody(fnOf('f', b.body([], b.arith('ADD', b.input('n'), b.layerVar('STEP'))), ['n']), layerOf({ STEP: 2 })).code;
    expect(code).toBe('return n + STEP;\n');
  });

  test('text_print calls print', () => {
    const b = new BodyBuilder('t');
    expect(generateBody(fnOf('f', b.body([b.print(b.str('hello'))], b.num(0))), layerOf()).code).toBe("print('hello');\nreturn 0;\n");
  });

  test('a block variable named like an API helper, an input or a layer variable is renamed', () => {
    const b = new BodyBuilder('t');
    const body = b.body([b.set('distance', b.num(1)), b.set('heading', b.num(2)), b.set('SPEED', b.num(3)), b.set('print', b.num(4))], b.input('heading'));
    const code = generateBody(fnOf('f', body, ['heading']), layerOf({ SPEED: 1 })).code;
    expect(code).toMatch(/^var distance2, heading2, SPEED2, print2;/);
    expect(code).toContain('return heading;');
  });

  test('the reserved words include every API name', () => {
    for (const name of Object.keys(API)) expect(RESERVED_NAMES).toContain(name);
  });

  test('Blockly random blocks are refused with a hint to use a random input', () => {
    const body = { blocks: { languageVersion: 0, blocks: [{ type: 'lb_function', id: 'r', inputs: { RETURN: { block: { type: 'math_random_float', id: 'x' } } } }] } };
    expect(() => generateBody(fnOf('f', body), layerOf())).toThrow(/random input/);
  });

  test('a missing return value is explained', () => {
    expect(() => generateBody(fnOf('f', emptyBody(), [], 'number'), layerOf())).toThrow('The function block\'s "return" socket is empty: attach the value the function gives (a number).');
  });

  test('an unknown block type is explained', () => {
    const body = { blocks: { languageVersion: 0, blocks: [{ type: 'lb_function', id: 'r', inputs: { RETURN: { block: { type: 'lb_teleport', id: 'x' } } } }] } };
    expect(() => generateBody(fnOf('f', body), layerOf())).toThrow(/does not know: "lb_teleport"/);
  });

  test('no function block, or two, is explained', () => {
    expect(() => generateBody(fnOf('f', { blocks: { languageVersion: 0, blocks: [] } }), layerOf())).toThrow(/has no "function f" block/);
    const root = { type: 'lb_function', inputs: { RETURN: { block: { type: 'math_number', fields: { NUM: 1 } } } } };
    expect(() => generateBody(fnOf('f', { blocks: { languageVersion: 0, blocks: [root, root] } }), layerOf())).toThrow(/2 "function" blocks/);
  });

  test('reading an input the function does not have is explained', () => {
    const b = new BodyBuilder('t');
    expect(() => generateBody(fnOf('f', b.body([], b.input('nope')), ['a']), layerOf())).toThrow('The "input" block reads "nope", but the function "f" has no input with that name. It has: a.');
  });

  test('an empty socket of an API block is explained', () => {
    const b = new BodyBuilder('t');
    expect(() => generateBody(fnOf('f', b.body([], b.api('distance', b.point(b.num(0), b.num(0)))), []), layerOf())).toThrow(/empty socket "b"/);
  });

  test('blocks that are not attached to the function block are ignored', () => {
    const b = new BodyBuilder('t');
    const body = b.body([], b.num(1)) as { blocks: { blocks: JsonValue[] } };
    body.blocks.blocks.push({ type: 'text_print', id: 'stray', x: 300, y: 0 });
    expect(generateBody(fnOf('f', body as unknown as JsonValue), layerOf()).code).toBe('return 1;\n');
  });

  test('the debug variant marks every statement with its block id', () => {
    const b = new BodyBuilder('t');
    const g = generateBody(fnOf('f', b.body([b.set('x', b.num(1))], b.get('x'))), layerOf());
    expect(g.debugCode).toBe("var x;\n__block('t.2');\nx = 1;\n__block('t.4');\nreturn x;\n");
  });

  test('results are cached by the body JSON and the names', () => {
    const b = new BodyBuilder('t');
    const fn = fnOf('f', b.body([], b.num(1)));
    expect(generateBody(fn, layerOf())).toBe(generateBody({ ...fn }, layerOf()));
    expect(generateBody(fn, layerOf())).not.toBe(generateBody(fn, layerOf({ A: 1 })));
  });

  test('generated code compiles into the functions the sandbox runs (ES5)', () => {
    const b = new BodyBuilder('t');
    const body = b.body([b.forEach('item', b.list(b.num(1), b.num(2)), [b.print(b.get('item'))])], b.move(b.num(0), b.num(1), b.num(0)));
    const [compiled] = compileController(controller([layer('L', [{ ...fnOf('changePos', body, [], 'move') }])]), generateBody);
    expect(compiled.source).not.toMatch(/\b(let|const|=>|class)\b|`/);
    expect(compiled.debugSource).toContain("__block('");
  });
});
