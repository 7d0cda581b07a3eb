/**
 * The JavaScript generator for Layerbot's blocks: Blockly's standard generators, with printing
 * routed to `print`, Blockly's unseeded random blocks refused, and Layerbot's own blocks. Names
 * of the native API, the function's inputs and its layer variables are reserved, so a block
 * variable never hides one of them (Blockly renames it, e.g. `heading2`).
 *
 * Block variables are declared with `var` at the start of the body that the engine wraps in the
 * function declaration: they are local to the function, which keeps functions pure.
 *
 * This file has no side effects.
 */
import type * as Blockly from 'blockly/core';
import { JavascriptGenerator, javascriptGenerator, Order } from 'blockly/javascript';
import { RESERVED_NAMES } from '../app/core/sandbox/api';
import type { BlockGenerator } from './types';
import { BlocksError } from './types';

/** The prefix that marks each statement with its block id in the debug variant of the code. */
export const DEBUG_STATEMENT_PREFIX = '__block(%1);\n';

export class LayerbotGenerator extends JavascriptGenerator {
  private readonly baseReservedWords: string;

  constructor() {
    super('JavaScript');
    this.addReservedWords(RESERVED_NAMES.join(','));
    this.baseReservedWords = this.RESERVED_WORDS_;
  }

  /**
   * Reserves the names of one function's inputs and layer variables (and nothing from earlier
   * functions), so the same blocks always generate the same code.
   */
  useFunctionNames(names: readonly string[]): void {
    this.RESERVED_WORDS_ = this.baseReservedWords + (names.length ? `${names.join(',')},` : '');
    this.nameDB_ = undefined;
  }

  /** The code of a value input, or a BlocksError naming the block and the empty socket. */
  requiredValue(block: Blockly.Block, input: string, order: Order, what: string): string {
    const code = this.valueToCode(block, input, order);
    if (!code) throw new BlocksError(`The "${what}" block has an empty socket "${input.toLowerCase()}": attach a value to it.`, block.id);
    return code;
  }
}

const printGenerator: BlockGenerator = (block, generator) => `print(${generator.valueToCode(block, 'TEXT', Order.NONE) || "''"});\n`;

const noRandom: BlockGenerator = (block) => {
  throw new BlocksError(
    'Random numbers come from a random input, so that a run can be replayed exactly: add a random source to the layer and an input from it to this function.',
    block.id,
  );
};

/** Blockly's standard generators with Layerbot's changes. */
export function standardGenerators(): Record<string, BlockGenerator> {
  return {
    ...(javascriptGenerator.forBlock as unknown as Record<string, BlockGenerator>),
    text_print: printGenerator,
    math_random_int: noRandom,
    math_random_float: noRandom,
  };
}
