/**
 * The contract every sandbox engine keeps (JS-Interpreter now, a faster one later): functions are
 * declared once, then called every tick with native, deeply frozen argument values; each call has
 * a step budget; results come back as native, deeply frozen values; failures are values.
 */

/** One student function, ready for a sandbox. */
export interface CompiledFunction {
  readonly name: string;
  readonly layer: string;
  /** Parameter names, in the order the arguments are passed (the function's inputs). */
  readonly params: readonly string[];
  /** A complete ES5 function declaration: `function NAME(p1, p2) { ... }`. */
  readonly source: string;
  /**
   * The same function with a `__block("id");` call before each block's statement, used to find
   * the block that failed and to step through a call block by block. Absent in text mode.
   */
  readonly debugSource?: string;
}

export type SandboxFailureKind =
  /** The code threw (a TypeError, a thrown value, ...). */
  | 'exception'
  /** The call ran out of steps: an infinite loop, or too much work for the budget. */
  | 'budget'
  /** The code tried to change one of its inputs. */
  | 'mutation'
  /** Too much memory or too deep a recursion. */
  | 'resources'
  /** The source does not parse. */
  | 'syntax';

export interface SandboxSuccess {
  readonly ok: true;
  /** The returned value: native and deeply frozen; an input returned unchanged keeps its identity. */
  readonly value: unknown;
  /** Lines printed during the call. */
  readonly output: readonly string[];
  /** Steps the call took. */
  readonly steps: number;
}

export interface SandboxFailure {
  readonly ok: false;
  readonly kind: SandboxFailureKind;
  /** What happened, in words a student understands (without the function/layer prefix). */
  readonly message: string;
  readonly output: readonly string[];
  /** The block that was running, when the engine knows it. */
  readonly blockId: string | null;
}

export type SandboxResult = SandboxSuccess | SandboxFailure;

/** A sandbox holding all functions of one controller. */
export interface Sandbox {
  /**
   * Calls function number `index` (in the order given to the factory) with native arguments.
   * Never throws for anything the student's code does.
   */
  call(index: number, args: readonly unknown[], budget: number): SandboxResult;
  /** Releases the sandbox's resources. */
  dispose(): void;
}

/** How every error of a function is told: `Error in function "arrived" (layer "Middle"): <detail>`. */
export function functionErrorMessage(functionName: string, layerName: string, detail: string): string {
  return `Error in function "${functionName}" (layer "${layerName}"): ${detail}`;
}

/** Raised by a factory when a function's source does not parse. */
export class CompileError extends Error {
  constructor(
    readonly functionName: string,
    readonly layerName: string,
    readonly detail: string,
  ) {
    super(functionErrorMessage(functionName, layerName, detail));
    this.name = 'CompileError';
  }
}

export type SandboxFactory = (functions: readonly CompiledFunction[]) => Sandbox;
