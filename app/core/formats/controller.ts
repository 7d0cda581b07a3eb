/**
 * Controller files (`*.controller.json`): reading with every problem explained, and writing.
 *
 * This module checks the file's shape (JSON Schema). Whether the controller makes sense as a
 * graph (arcs from functions that exist, no cycles within a tick, unique names, a body command)
 * is checked by validateController in app/core/controller/validate.ts, which names the same JSON
 * paths.
 */
import type { ArcSource, ControllerSpec, FunctionBody, FunctionSpec, InputSpec, LayerSpec, LayerVariable, RandomSourceSpec } from '../controller/model';
import { deepFreeze } from '../values';
import type { Result } from './types';
import { fail, ok } from './types';
import type { JsonDocument } from './json';
import { parseJsonText } from './json';
import { CURRENT_VERSION, FORMATS, openEnvelope } from './envelope';
import { schemaProblems } from './validator';
import type { SchemaValidator } from './validator';
import { prettyJson } from './pretty';
import controllerSchema from './schemas/controller.schema.json';
import validateControllerSchema from './generated/controller.validate';

/** The controller file's JSON Schema (for editors, and for the app to offer). */
export const CONTROLLER_SCHEMA: object = controllerSchema;

/** Reads a controller file. `fileName` only names the file in problems. */
export function parseController(text: string, fileName: string): Result<ControllerSpec> {
  const json = parseJsonText(text, fileName);
  if (!json.ok) return json;
  const envelope = openEnvelope(json.value, 'controller', fileName);
  if (!envelope.ok) return fail(envelope.problems);
  const doc: JsonDocument = { value: envelope.value, positionOf: json.value.positionOf };
  const shape = schemaProblems(validateControllerSchema as SchemaValidator, controllerSchema, doc, fileName);
  if (shape.length) return fail(shape);
  return ok(deepFreeze(toControllerSpec(envelope.value as unknown as ControllerFile)));
}

/** The JSON a controller file holds, once its schema has checked it. */
interface ControllerFile {
  name: string;
  description?: string;
  bodyCommand: string;
  stepBudget?: number;
  layers: {
    name: string;
    description?: string;
    variables?: LayerVariable[];
    randomSources?: RandomSourceSpec[];
    functions: FunctionSpec[];
  }[];
}

/** Copies exactly the model's fields (dropping `$schema` and the like) and fills in defaults. */
function toControllerSpec(f: ControllerFile): ControllerSpec {
  return {
    name: f.name,
    ...optional('description', f.description),
    bodyCommand: f.bodyCommand,
    ...optional('stepBudget', f.stepBudget),
    layers: f.layers.map(
      (l): LayerSpec => ({
        name: l.name,
        ...optional('description', l.description),
        variables: (l.variables ?? []).map((v) => ({ name: v.name, value: v.value })),
        randomSources: (l.randomSources ?? []).map(copyRandomSource),
        functions: l.functions.map(copyFunction),
      }),
    ),
  };
}

function copyRandomSource(r: RandomSourceSpec): RandomSourceSpec {
  return { name: r.name, type: r.type, seed: r.seed, ...optional('min', r.min), ...optional('max', r.max) };
}

function copyFunction(fn: FunctionSpec): FunctionSpec {
  return {
    name: fn.name,
    ...optional('description', fn.description),
    output: fn.output,
    inputs: fn.inputs.map((i): InputSpec => ({ name: i.name, from: copyArc(i.from) })),
    body: copyBody(fn.body),
  };
}

function copyArc(a: ArcSource): ArcSource {
  switch (a.kind) {
    case 'function':
      return { kind: 'function', function: a.function };
    case 'previous':
      return { kind: 'previous', function: a.function, initial: a.initial };
    case 'world':
      return { kind: 'world', input: a.input };
    case 'random':
      return { kind: 'random', source: a.source };
  }
}

function copyBody(b: FunctionBody): FunctionBody {
  return b.kind === 'blocks' ? { kind: 'blocks', blocks: b.blocks } : { kind: 'text', code: b.code };
}

/** `{ key: value }` when the value is present, `{}` otherwise (keeps optional fields truly absent). */
function optional<K extends string, V>(key: K, value: V | undefined): { [P in K]?: V } {
  return value === undefined ? {} : ({ [key]: value } as { [P in K]?: V });
}

/** Layers and functions always get a line per field, even when short, so every file looks alike. */
const EXPANDED = /^\$\.layers(\[\d+\](\.functions(\[\d+\])?)?)?$/;

/**
 * A controller as file text: pretty JSON, `format` and `version` first, then a fixed order of
 * fields; empty `variables` and `randomSources` are written out so students see where they go.
 * Throws a SerializeError (with the JSON path) for values JSON cannot hold, such as Infinity.
 */
export function serializeController(spec: ControllerSpec): string {
  return prettyJson({
    format: FORMATS.controller,
    version: CURRENT_VERSION.controller,
    name: spec.name,
    description: spec.description,
    bodyCommand: spec.bodyCommand,
    stepBudget: spec.stepBudget,
    layers: spec.layers.map((l) => ({
      name: l.name,
      description: l.description,
      variables: l.variables.map((v) => ({ name: v.name, value: v.value })),
      randomSources: l.randomSources.map(copyRandomSource),
      functions: l.functions.map(copyFunction),
    })),
  }, (path) => EXPANDED.test(path));
}
