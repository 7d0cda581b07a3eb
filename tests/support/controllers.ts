/** Small controllers built in code for unit tests. */
import type { ControllerSpec, FunctionSpec, InputSpec, LayerSpec } from '../../app/core/controller/model';
import type { ValueType } from '../../app/core/values';

export function fn(name: string, output: ValueType, inputs: InputSpec[], code: string): FunctionSpec {
  return { name, output, inputs, body: { kind: 'text', code } };
}

export function layer(name: string, functions: FunctionSpec[], extra: Partial<LayerSpec> = {}): LayerSpec {
  return { name, variables: [], randomSources: [], functions, ...extra };
}

export function controller(layers: LayerSpec[], bodyCommand = 'changePos'): ControllerSpec {
  return { name: 'test', bodyCommand, layers };
}

/** A body command that moves one unit along a fixed heading. */
export const forward = (heading = 0): FunctionSpec =>
  fn('changePos', 'move', [], `return { heading: ${heading}, dx: Math.cos(${heading} * Math.PI / 180), dy: Math.sin(${heading} * Math.PI / 180) };`);

export const world = {
  name: 'open',
  walls: [],
  goals: [{ name: 'g', x: 10, y: 0 }],
  plan: ['g'],
  robot: { x: 0, y: 0, heading: 0 },
};
