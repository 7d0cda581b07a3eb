/**
 * Loading worlds and controllers from files for the command line, with every problem named by
 * file and JSON path. Shared by `run`, `check`, `grade` and `bench`.
 */
import { ControllerInvalidError, Session } from '../core/session/session';
import type { SessionOptions } from '../core/session/session';
import type { ControllerSpec } from '../core/controller/model';
import { validateController } from '../core/controller/validate';
import { compileController } from '../core/controller/compile';
import { parseController, parseWorld } from '../core/formats';
import type { WorldSpec } from '../core/world/world';
import { createInterpreterSandbox } from '../core/sandbox/interpreter';
import { CompileError } from '../core/sandbox/types';
import { generateBody } from '../../blocks/generate';
import { readTextFile } from './files';

/** A problem with the user's input: printed, and the command exits with code 2. */
export class InputError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'InputError';
  }
}

export function loadWorld(file: string): WorldSpec {
  const parsed = parseWorld(readText(file), file);
  if (!parsed.ok) throw new InputError(parsed.problems.map((p) => `${p.file}: ${p.path}: ${p.message}`).join('\n'));
  return parsed.value;
}

export function loadController(file: string): ControllerSpec {
  const parsed = parseController(readText(file), file);
  if (!parsed.ok) throw new InputError(parsed.problems.map((p) => `${p.file}: ${p.path}: ${p.message}`).join('\n'));
  const problems = validateController(parsed.value);
  if (problems.length) throw new InputError(problems.map((p) => `${file}: ${p.path}: ${p.message}`).join('\n'));
  return parsed.value;
}

/** Compiles every function (generating blocks) and parses it in the sandbox; throws InputError on failure. */
export function checkCompiles(spec: ControllerSpec, file: string): void {
  try {
    createInterpreterSandbox(compileController(spec, generateBody)).dispose();
  } catch (e) {
    throw new InputError(`${file}: ${e instanceof Error ? e.message : String(e)}`);
  }
}

export const defaultSessionOptions = (seed?: number): SessionOptions => ({
  sandbox: createInterpreterSandbox,
  generateBody,
  ...(seed !== undefined ? { seed } : {}),
});

/** A session for a world and controller, with load problems turned into InputErrors. */
export function createSession(world: WorldSpec, controller: ControllerSpec, file: string, options: SessionOptions): Session {
  try {
    return new Session(world, controller, options);
  } catch (e) {
    if (e instanceof ControllerInvalidError) throw new InputError(e.problems.map((p) => `${file}: ${p.path}: ${p.message}`).join('\n'));
    if (e instanceof CompileError || e instanceof Error) throw new InputError(`${file}: ${e.message}`);
    throw e;
  }
}

function readText(file: string): string {
  try {
    return readTextFile(file);
  } catch (e) {
    throw new InputError(e instanceof Error ? e.message : String(e));
  }
}
