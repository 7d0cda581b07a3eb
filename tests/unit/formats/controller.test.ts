import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { detectFormat, formatProblems, parseController, SerializeError, serializeController } from '../../../app/core/formats';
import type { FileProblem } from '../../../app/core/formats';
import type { ControllerSpec } from '../../../app/core/controller/model';
import { RANDOM_TYPES, WORLD_INPUTS } from '../../../app/core/controller/model';
import { VALUE_TYPES } from '../../../app/core/values';
import controllerSchema from '../../../app/core/formats/schemas/controller.schema.json';

const BASIC = join(__dirname, '../../../examples/controllers/basic.controller.json');

function problemsOf(text: string): readonly FileProblem[] {
  const r = parseController(text, 'c.controller.json');
  if (r.ok) throw new Error('expected problems');
  return r.problems;
}
const text = (o: unknown) => JSON.stringify(o, null, 2);
const pathsAndMessages = (ps: readonly FileProblem[]) => ps.map((p) => `${p.path}: ${p.message}`);

/** A valid controller file as an object, to spoil one field at a time. */
function base(): { layers: ({ functions: Record<string, unknown>[] } & Record<string, unknown>)[] } & Record<string, unknown> {
  return {
    format: 'layerbot-controller',
    version: 1,
    name: 'Tiny',
    bodyCommand: 'changePos',
    layers: [
      {
        name: 'Top',
        functions: [
          {
            name: 'steer',
            output: 'number',
            inputs: [{ name: 'pos', from: { kind: 'world', input: 'robotPos' } }],
            body: { kind: 'text', code: 'return pos[0];' },
          },
        ],
      },
      {
        name: 'Bottom',
        variables: [{ name: 'TURN', value: 18 }],
        randomSources: [{ name: 'coin', type: 'int', seed: 42, min: 0, max: 1 }],
        functions: [
          {
            name: 'changePos',
            description: 'moves',
            output: 'move',
            inputs: [
              { name: 'steer', from: { kind: 'function', function: 'steer' } },
              { name: 'last', from: { kind: 'previous', function: 'changePos', initial: { heading: 0, dx: 0, dy: 0 } } },
              { name: 'flip', from: { kind: 'random', source: 'coin' } },
            ],
            body: { kind: 'blocks', blocks: { blocks: { languageVersion: 0, blocks: [{ type: 'procedures_defreturn', id: 'b1' }] } } },
          },
        ],
      },
    ],
  };
}

describe('parseController', () => {
  it('reads the basic example and round-trips it', () => {
    const source = readFileSync(BASIC, 'utf8');
    expect(detectFormat(source)).toBe('controller');
    const r = parseController(source, 'basic.controller.json');
    if (!r.ok) throw new Error(formatProblems(r.problems));
    expect(r.value.bodyCommand).toBe('changePos');
    const again = parseController(serializeController(r.value), 'again');
    expect(again.ok && again.value).toEqual(r.value);
  });

  it('fills in defaults and freezes the result deeply', () => {
    const r = parseController(text(base()), 'c');
    if (!r.ok) throw new Error(formatProblems(r.problems));
    const c: ControllerSpec = r.value;
    expect(c.layers[0].variables).toEqual([]);
    expect(c.layers[0].randomSources).toEqual([]);
    expect(c.layers[1].randomSources[0]).toEqual({ name: 'coin', type: 'int', seed: 42, min: 0, max: 1 });
    expect('description' in c.layers[0].functions[0]).toBe(false);
    expect('stepBudget' in c).toBe(false);
    const body = c.layers[1].functions[0].body;
    expect(Object.isFrozen(c) && Object.isFrozen(c.layers[1].functions[0].inputs[1].from) && Object.isFrozen(body)).toBe(true);
    expect(body.kind === 'blocks' && Object.isFrozen((body.blocks as { blocks: object }).blocks)).toBe(true);
  });

  it.each<[string, (o: ReturnType<typeof base>) => void, string[]]>([
    ['a bad arc kind', (o) => (o.layers[1].functions[0].inputs = [{ name: 'a', from: { kind: 'fn', function: 'steer' } }]), [
      '$.layers[1].functions[0].inputs[0].from.kind: must be one of: function, previous, world, random; found "fn"',
    ]],
    ['an arc without a kind', (o) => (o.layers[1].functions[0].inputs = [{ name: 'a', from: { function: 'steer' } }]), [
      '$.layers[1].functions[0].inputs[0].from: missing field "kind"; it must be one of: function, previous, world, random',
    ]],
    ['an arc kind that is not text', (o) => (o.layers[1].functions[0].inputs = [{ name: 'a', from: { kind: 3 } }]), [
      '$.layers[1].functions[0].inputs[0].from.kind: must be one of: function, previous, world, random; found 3',
    ]],
    ['a previous arc without an initial value', (o) => (o.layers[1].functions[0].inputs = [{ name: 'a', from: { kind: 'previous', function: 'steer' } }]), [
      '$.layers[1].functions[0].inputs[0].from: missing field "initial": the value this input has on the first tick, before the function has ever run: any JSON value',
    ]],
    ['a field of another arc kind', (o) => (o.layers[0].functions[0].inputs = [{ name: 'a', from: { kind: 'world', input: 'heading', function: 'x' } }]), [
      '$.layers[0].functions[0].inputs[0].from.function: unknown field "function"; allowed: kind, input',
    ]],
    ['an unknown world input', (o) => (o.layers[0].functions[0].inputs = [{ name: 'a', from: { kind: 'world', input: 'whiskers' } }]), [
      '$.layers[0].functions[0].inputs[0].from.input: must be one of: robotPos, heading, whisker, walls, goals, plan, tick, crashed; found "whiskers" (did you mean "whisker"?)',
    ]],
    ['a bad output type', (o) => (o.layers[0].functions[0].output = 'int'), [
      '$.layers[0].functions[0].output: must be one of: number, boolean, string, list, point, record, move, any; found "int"',
    ]],
    ['a bad name', (o) => (o.layers[0].functions[0].name = 'my steer'), [
      '$.layers[0].functions[0].name: "my steer" is not a valid name: a name starts with a letter or _ and holds only letters, digits and _ (no spaces or other signs)',
    ]],
    ['a bad input name', (o) => (o.layers[0].functions[0].inputs = [{ name: '1st', from: { kind: 'world', input: 'tick' } }]), [
      '$.layers[0].functions[0].inputs[0].name: "1st" is not a valid name: a name starts with a letter or _ and holds only letters, digits and _ (no spaces or other signs)',
    ]],
    ['a text body without code', (o) => (o.layers[0].functions[0].body = { kind: 'text', blocks: {} }), [
      '$.layers[0].functions[0].body: missing field "code": the body of a JavaScript function: the inputs and layer variables are in scope by name, and it must return the output',
      '$.layers[0].functions[0].body.blocks: unknown field "blocks"; allowed: kind, code',
    ]],
    ['a body of an unknown kind', (o) => (o.layers[0].functions[0].body = { kind: 'python', code: '' }), [
      '$.layers[0].functions[0].body.kind: must be one of: blocks, text; found "python"',
    ]],
    ['blocks that are not an object', (o) => (o.layers[1].functions[0].body = { kind: 'blocks', blocks: 'x' }), [
      '$.layers[1].functions[0].body.blocks: expected an object {...}, found "x"',
    ]],
    ['an unknown layer field', (o) => ((o.layers[0] as Record<string, unknown>).colour = 'red'), [
      '$.layers[0].colour: unknown field "colour"; allowed: name, description, variables, randomSources, functions',
    ]],
    ['a missing function list', (o) => delete (o.layers[0] as Record<string, unknown>).functions, [
      "$.layers[0]: missing field \"functions\": the layer's functions",
    ]],
    ['a bad random source', (o) => ((o.layers[1] as Record<string, unknown>).randomSources = [{ name: 'r', type: 'dice', seed: 1.5 }]), [
      '$.layers[1].randomSources[0].type: must be one of: boolean, double, float, int, long, gaussian; found "dice"',
      '$.layers[1].randomSources[0].seed: expected a whole number, found 1.5',
    ]],
    ['a variable without a value', (o) => ((o.layers[1] as Record<string, unknown>).variables = [{ name: 'X' }]), [
      '$.layers[1].variables[0]: missing field "value": the constant\'s value: any JSON value (a number, text, true/false, a list or a record)',
    ]],
    ['a step budget of zero', (o) => (o.stepBudget = 0), ['$.stepBudget: expected a number at least 1, found 0']],
    ['layers that are not a list', (o) => ((o as Record<string, unknown>).layers = {}), [
      '$.layers: expected a list [...], found an object {...}',
    ]],
  ])('explains %s', (_what, spoil, expected) => {
    const o = base();
    spoil(o);
    expect(pathsAndMessages(problemsOf(text(o)))).toEqual(expected);
  });

  it('says so when a world is opened as a controller', () => {
    const world = readFileSync(join(__dirname, '../../../examples/worlds/office.world.json'), 'utf8');
    expect(pathsAndMessages(problemsOf(world))).toEqual(['$.format: this file is a Layerbot world, not a controller; open it as a world']);
  });

  it('refuses controllers from a newer Layerbot', () => {
    expect(pathsAndMessages(problemsOf(text({ ...base(), version: 7 })))).toEqual([
      '$.version: this controller was made by a newer Layerbot (format version 7; this Layerbot reads versions up to 1); update Layerbot to open it',
    ]);
  });

  it('leaves graph checks (unknown sources, cycles) to validateController', () => {
    const o = base();
    o.layers[0].functions[0].inputs = [{ name: 'a', from: { kind: 'function', function: 'nobody' } }];
    expect(parseController(text(o), 'c').ok).toBe(true);
  });
});

describe('the controller schema', () => {
  const defs = controllerSchema.definitions;
  it('lists the same choices as the model', () => {
    expect(defs.function.properties.output.enum).toEqual([...VALUE_TYPES]);
    expect(defs.randomSource.properties.type.enum).toEqual([...RANDOM_TYPES]);
    expect(defs.worldArc.properties.input.enum).toEqual([...WORLD_INPUTS]);
    expect(defs.identifier.pattern).toBe('^[A-Za-z_][A-Za-z0-9_]*$');
  });
});

describe('serializeController', () => {
  it('writes format and version first and keeps empty lists visible', () => {
    const r = parseController(text(base()), 'c');
    if (!r.ok) throw new Error(formatProblems(r.problems));
    const out = serializeController(r.value);
    expect(out.split('\n').slice(0, 6)).toEqual([
      '{',
      '  "format": "layerbot-controller",',
      '  "version": 1,',
      '  "name": "Tiny",',
      '  "bodyCommand": "changePos",',
      '  "layers": [',
    ]);
    expect(out).toContain('"variables": [],\n');
    expect(out).toContain('"inputs": [{ "name": "pos", "from": { "kind": "world", "input": "robotPos" } }],');
    expect(serializeController(JSON.parse(JSON.stringify(r.value)) as ControllerSpec)).toBe(out);
  });

  it('refuses values JSON cannot hold, naming where they are', () => {
    const r = parseController(text(base()), 'c');
    if (!r.ok) throw new Error('parse failed');
    const bad: ControllerSpec = {
      ...r.value,
      layers: [{ ...r.value.layers[1], variables: [{ name: 'BIG', value: Infinity }] }],
    };
    expect(() => serializeController(bad)).toThrow(SerializeError);
    expect(() => serializeController(bad)).toThrow('$.layers[0].variables[0].value: Infinity cannot be written in a JSON file');
  });
});
