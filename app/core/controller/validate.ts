/**
 * Checks a controller as a whole graph and explains every problem in words a student can act on:
 * names that clash, arcs from sources that do not exist, cycles within a tick, a missing body
 * command. (The file's shape is checked earlier, by its JSON Schema.)
 */
import { RESERVED_NAMES } from '../sandbox/api';
import type { ControllerSpec } from './model';
import { allFunctions, WORLD_INPUTS } from './model';
import { explainCycle, orderFunctions } from './graph';

export interface ControllerProblem {
  /** Where: a JSON path into the controller file, e.g. `$.layers[1].functions[0].inputs[2]`. */
  readonly path: string;
  readonly message: string;
}

const IDENTIFIER = /^[A-Za-z_][A-Za-z0-9_]*$/;

/** Words the generated JavaScript relies on, which no student name may take. */
const JS_WORDS = new Set(
  ('break case catch class const continue debugger default delete do else enum export extends false finally for function if ' +
    'import in instanceof new null return super switch this throw true try typeof var void while with yield let static ' +
    'implements interface package private protected public await arguments eval undefined NaN Infinity Math JSON Object Array ' +
    'String Number Boolean Date RegExp Error TypeError RangeError isNaN isFinite parseInt parseFloat').split(' '),
);

/** Every problem of the controller, in file order; empty when it can run. */
export function validateController(spec: ControllerSpec): ControllerProblem[] {
  const problems: ControllerProblem[] = [];
  const add = (path: string, message: string) => problems.push({ path, message });
  const functions = new Map<string, string>();
  const sources = new Map<string, string>();
  const reserved = new Set(RESERVED_NAMES);

  const checkName = (path: string, what: string, name: string) => {
    if (!IDENTIFIER.test(name)) add(path, `The ${what} name "${name}" must start with a letter and hold only letters, digits and _.`);
    else if (JS_WORDS.has(name) || reserved.has(name)) add(path, `"${name}" is a word Layerbot keeps for itself; choose another ${what} name.`);
  };

  const layerNames = new Set<string>();
  spec.layers.forEach((layer, li) => {
    const lp = `$.layers[${li}]`;
    if (layerNames.has(layer.name)) add(`${lp}.name`, `Two layers are named "${layer.name}"; layer names must differ.`);
    layerNames.add(layer.name);
    const varNames = new Set<string>();
    layer.variables.forEach((v, vi) => {
      checkName(`${lp}.variables[${vi}].name`, 'layer variable', v.name);
      if (varNames.has(v.name)) add(`${lp}.variables[${vi}].name`, `Layer "${layer.name}" has two variables named "${v.name}".`);
      varNames.add(v.name);
    });
    layer.randomSources.forEach((r, ri) => {
      const rp = `${lp}.randomSources[${ri}]`;
      checkName(`${rp}.name`, 'random source', r.name);
      const other = sources.get(r.name);
      if (other !== undefined) add(`${rp}.name`, `There are two random sources named "${r.name}" (layers "${other}" and "${layer.name}").`);
      sources.set(r.name, layer.name);
      if ((r.type === 'int' || r.type === 'long') && r.min !== undefined && r.max !== undefined && r.min > r.max) {
        add(rp, `Random source "${r.name}": the smallest value (${r.min}) is larger than the largest (${r.max}).`);
      }
    });
    layer.functions.forEach((fn, fi) => {
      const fp = `${lp}.functions[${fi}]`;
      checkName(`${fp}.name`, 'function', fn.name);
      const other = functions.get(fn.name);
      if (other !== undefined) add(`${fp}.name`, `There are two functions named "${fn.name}" (layers "${other}" and "${layer.name}").`);
      functions.set(fn.name, layer.name);
      const seen = new Map<string, number>();
      fn.inputs.forEach((inp, ii) => {
        checkName(`${fp}.inputs[${ii}].name`, 'input', inp.name);
        const first = seen.get(inp.name);
        if (first !== undefined) {
          add(
            `${fp}.inputs[${ii}].name`,
            `Function "${fn.name}" (layer "${layer.name}") has two inputs named "${inp.name}" ` +
              `(arcs ${first + 1} and ${ii + 1}, from ${describeSource(fn.inputs[first].from)} and ${describeSource(inp.from)}); rename one.`,
          );
        } else seen.set(inp.name, ii);
        if (varNames.has(inp.name)) {
          add(`${fp}.inputs[${ii}].name`, `Function "${fn.name}": input "${inp.name}" has the name of a variable of layer "${layer.name}"; rename one.`);
        }
      });
    });
  });

  // Arcs can name functions and sources of any layer, so check them once every name is known.
  spec.layers.forEach((layer, li) =>
    layer.functions.forEach((fn, fi) =>
      fn.inputs.forEach((inp, ii) => {
        const path = `$.layers[${li}].functions[${fi}].inputs[${ii}].from`;
        const from = inp.from;
        const where = `Function "${fn.name}" (layer "${layer.name}"), input "${inp.name}"`;
        if ((from.kind === 'function' || from.kind === 'previous') && !functions.has(from.function)) {
          add(path, `${where} reads the function "${from.function}", but there is no function by that name.${suggest(from.function, [...functions.keys()])}`);
        } else if (from.kind === 'world' && !(WORLD_INPUTS as readonly string[]).includes(from.input)) {
          add(path, `${where} reads the world input "${from.input}", which does not exist. World inputs: ${WORLD_INPUTS.join(', ')}.`);
        } else if (from.kind === 'random' && !sources.has(from.source)) {
          add(path, `${where} reads the random source "${from.source}", but there is none by that name.${suggest(from.source, [...sources.keys()])}`);
        } else if (from.kind === 'function' && from.function === fn.name) {
          add(path, `${where} reads the function's own output in the same tick. Take it from the previous tick instead.`);
        }
      }),
    ),
  );

  if (!functions.has(spec.bodyCommand)) {
    add(
      '$.bodyCommand',
      spec.bodyCommand
        ? `The body command is the function "${spec.bodyCommand}", but there is no function by that name. It should name the function that returns the move {heading, dx, dy} (usually "changePos").`
        : 'No function is named as the body command: name the function that returns the move {heading, dx, dy} (usually "changePos").',
    );
  } else {
    const body = allFunctions(spec).find((f) => f.fn.name === spec.bodyCommand)!;
    if (body.fn.output !== 'move' && body.fn.output !== 'any') {
      add('$.bodyCommand', `The body command "${spec.bodyCommand}" must return a move {heading, dx, dy}, but it is declared to return ${body.fn.output}.`);
    }
  }

  if (problems.length === 0) {
    const ordering = orderFunctions(spec);
    if (!ordering.ok) add('$.layers', explainCycle(ordering.cycle));
  }
  return problems;
}

function describeSource(from: ControllerSpec['layers'][number]['functions'][number]['inputs'][number]['from']): string {
  switch (from.kind) {
    case 'function':
      return `"${from.function}"`;
    case 'previous':
      return `"${from.function}" (previous tick)`;
    case 'world':
      return `the world's "${from.input}"`;
    case 'random':
      return `the random source "${from.source}"`;
  }
}

function suggest(name: string, known: string[]): string {
  const lower = name.toLowerCase();
  const close = known.find((k) => k.toLowerCase() === lower || editDistance(k.toLowerCase(), lower) <= 2);
  return close ? ` Did you mean "${close}"?` : '';
}

function editDistance(a: string, b: string): number {
  const d = Array.from({ length: a.length + 1 }, (_, i) => [i, ...new Array<number>(b.length).fill(0)]);
  for (let j = 1; j <= b.length; j++) d[0][j] = j;
  for (let i = 1; i <= a.length; i++) {
    for (let j = 1; j <= b.length; j++) {
      d[i][j] = Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] === b[j - 1] ? 0 : 1));
    }
  }
  return d[a.length][b.length];
}
