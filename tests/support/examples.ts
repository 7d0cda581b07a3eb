/** Loads the example worlds and controllers the way the CLI does, and runs them. */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { ControllerSpec } from '../../app/core/controller/model';
import { parseController, parseWorld } from '../../app/core/formats';
import { createInterpreterSandbox } from '../../app/core/sandbox/interpreter';
import type { SandboxFactory } from '../../app/core/sandbox/types';
import { Session } from '../../app/core/session/session';
import type { WorldSpec } from '../../app/core/world/world';
import { generateBody } from '../../blocks/generate';

export const ROOT = join(__dirname, '..', '..');

export function exampleWorld(name: string): WorldSpec {
  const file = join(ROOT, 'examples', 'worlds', `${name}.world.json`);
  const parsed = parseWorld(readFileSync(file, 'utf8'), file);
  if (!parsed.ok) throw new Error(JSON.stringify(parsed.problems));
  return parsed.value;
}

export function exampleController(name: string): ControllerSpec {
  const file = join(ROOT, 'examples', 'controllers', `${name}.controller.json`);
  const parsed = parseController(readFileSync(file, 'utf8'), file);
  if (!parsed.ok) throw new Error(JSON.stringify(parsed.problems));
  return parsed.value;
}

/** A session of an example controller in an example world, with the reference engine. */
export function exampleSession(controller: string, world: string, sandbox: SandboxFactory = createInterpreterSandbox): Session {
  return new Session(exampleWorld(world), exampleController(controller), { sandbox, generateBody });
}
