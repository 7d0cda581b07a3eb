/**
 * What a function-body workspace knows about the function it edits: its name, declared output,
 * input names and its layer's variable names. The body blocks read names from here (dropdowns)
 * and the generator checks them. The body JSON itself stores no copy, so renaming an arc or a
 * layer variable in the controller editor never leaves a stale list inside the body.
 *
 * This file has no side effects.
 */
import type * as Blockly from 'blockly/core';
import type { FunctionSpec, LayerSpec } from '../app/core/controller/model';
import type { ValueType } from '../app/core/values';

export interface FunctionContext {
  readonly name: string;
  readonly output: ValueType;
  readonly inputs: readonly string[];
  readonly variables: readonly string[];
}

const contexts = new WeakMap<Blockly.Workspace, FunctionContext>();

export function contextOf(fn: FunctionSpec, layer: Pick<LayerSpec, 'variables'>): FunctionContext {
  return { name: fn.name, output: fn.output, inputs: fn.inputs.map((i) => i.name), variables: layer.variables.map((v) => v.name) };
}

/** Tells a body workspace which function it edits (call it before or after loading the body). */
export function setFunctionContext(workspace: Blockly.Workspace, context: FunctionContext): void {
  contexts.set(workspace, context);
  for (const block of workspace.getBlocksByType('lb_function', false)) refreshFunctionLabels(block, context);
}

export function getFunctionContext(workspace: Blockly.Workspace | null | undefined): FunctionContext | null {
  return workspace ? (contexts.get(workspace) ?? null) : null;
}

/** Shows the function's name and output type on its root block. */
export function refreshFunctionLabels(block: Blockly.Block, context: FunctionContext): void {
  block.getField('NAME')?.setValue(context.name);
  block.getField('OUTPUT')?.setValue(context.output);
}
