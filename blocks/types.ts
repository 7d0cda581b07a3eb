/**
 * The shape every block file exports: its JSON definitions and its generators. Definition files
 * register nothing; `index.ts` registers them all.
 *
 * This file has no side effects.
 */
import type * as Blockly from 'blockly/core';
import type { Order } from 'blockly/javascript';
import type { LayerbotGenerator } from './generator';

export type BlockGenerator = (block: Blockly.Block, generator: LayerbotGenerator) => [string, Order] | string | null;

/** A block definition in Blockly's JSON format. */
export type BlockJson = { readonly type: string } & Record<string, unknown>;

export interface BlockFamily {
  readonly definitions: readonly BlockJson[];
  readonly generators: Readonly<Record<string, BlockGenerator>>;
  /** Optional Blockly mixins/extensions needed by the definitions, by name. */
  readonly extensions?: Readonly<Record<string, (this: Blockly.Block) => void>>;
  /** Mixins that save and load extra state (Blockly calls these "mutators"), by name. */
  readonly mutators?: Readonly<Record<string, object>>;
}

/** Colours (hues) of the toolbox categories and their blocks. */
export const COLOURS = {
  inputs: 20,
  function: 0,
  logic: 210,
  loops: 120,
  math: 230,
  text: 160,
  lists: 260,
  geometry: 190,
  world: 35,
  grid: 65,
  variables: 330,
  helpers: 290,
  controller: 0,
  layer: 200,
  arc: 40,
  random: 300,
} as const;

/** A student-readable error raised while generating code from blocks. */
export class BlocksError extends Error {
  constructor(
    message: string,
    readonly blockId: string | null = null,
  ) {
    super(message);
    this.name = 'BlocksError';
  }
}
