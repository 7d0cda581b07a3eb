/**
 * The controller model: an ordered stack of layers (top first), each with layer variables, random
 * sources and functions. Functions are wired by arcs: each named input takes its value from a
 * source. Layers group functions for the student; the engine sees a dataflow graph.
 */
import type { JsonValue, ValueType } from '../values';

/** The world inputs a function can read, computed from the world after the previous tick. */
export const WORLD_INPUTS = ['robotPos', 'heading', 'whisker', 'walls', 'goals', 'plan', 'tick', 'crashed'] as const;
export type WorldInputName = (typeof WORLD_INPUTS)[number];

export const WORLD_INPUT_DOCS: Record<WorldInputName, { type: ValueType; doc: string }> = {
  robotPos: { type: 'point', doc: "The robot's position [x, y]." },
  heading: { type: 'number', doc: "The robot's heading in degrees, counter-clockwise from east, in [0, 360)." },
  whisker: { type: 'boolean', doc: "True when the body's whisker touches a wall." },
  walls: { type: 'list', doc: 'Every wall as [[x0, y0], [x1, y1]].' },
  goals: { type: 'list', doc: 'Every goal as {name, x, y}.' },
  plan: { type: 'list', doc: 'The names of the goals to visit, in order.' },
  tick: { type: 'number', doc: 'The number of the tick being computed (1 for the first).' },
  crashed: { type: 'boolean', doc: 'True once the robot has crashed into a wall.' },
};

/** Kinds of random source, after the original design's Java random inputs. */
export const RANDOM_TYPES = ['boolean', 'double', 'float', 'int', 'long', 'gaussian'] as const;
export type RandomType = (typeof RANDOM_TYPES)[number];

/** Where an input's value comes from. */
export type ArcSource =
  /** Another function's output from this tick. */
  | { readonly kind: 'function'; readonly function: string }
  /** Another function's output from the previous tick (a matching port); `initial` on tick 1. */
  | { readonly kind: 'previous'; readonly function: string; readonly initial: JsonValue }
  /** A world input. */
  | { readonly kind: 'world'; readonly input: WorldInputName }
  /** A seeded random source declared on a layer. */
  | { readonly kind: 'random'; readonly source: string };

/** One named input of a function: an arc from a source. */
export interface InputSpec {
  readonly name: string;
  readonly from: ArcSource;
}

/** A function's body: Blockly blocks (the usual case) or JavaScript text ("text mode"). */
export type FunctionBody =
  | { readonly kind: 'blocks'; readonly blocks: JsonValue }
  | { readonly kind: 'text'; readonly code: string };

export interface FunctionSpec {
  readonly name: string;
  readonly description?: string;
  readonly output: ValueType;
  readonly inputs: readonly InputSpec[];
  readonly body: FunctionBody;
}

export interface LayerVariable {
  readonly name: string;
  readonly value: JsonValue;
}

export interface RandomSourceSpec {
  readonly name: string;
  readonly type: RandomType;
  readonly seed: number;
  /** For "int" and "long": the smallest and largest value (inclusive). */
  readonly min?: number;
  readonly max?: number;
}

export interface LayerSpec {
  readonly name: string;
  readonly description?: string;
  readonly variables: readonly LayerVariable[];
  readonly randomSources: readonly RandomSourceSpec[];
  readonly functions: readonly FunctionSpec[];
}

/** A controller as its file describes it (without the file's format and version fields). */
export interface ControllerSpec {
  readonly name: string;
  readonly description?: string;
  /** The function whose output is the body command {heading, dx, dy} (the original `changePos`). */
  readonly bodyCommand: string;
  /** Steps one function call may take in the sandbox before it is stopped. */
  readonly stepBudget?: number;
  /** Top layer first. */
  readonly layers: readonly LayerSpec[];
}

export const DEFAULT_STEP_BUDGET = 5_000_000;

/** A function together with the layer that holds it. */
export interface PlacedFunction {
  readonly fn: FunctionSpec;
  readonly layer: LayerSpec;
}

/** Every function of the controller, top layer first, in the order the file lists them. */
export function allFunctions(spec: ControllerSpec): PlacedFunction[] {
  return spec.layers.flatMap((layer) => layer.functions.map((fn) => ({ fn, layer })));
}

/** Every random source of the controller with its layer. */
export function allRandomSources(spec: ControllerSpec): { source: RandomSourceSpec; layer: LayerSpec }[] {
  return spec.layers.flatMap((layer) => layer.randomSources.map((source) => ({ source, layer })));
}
