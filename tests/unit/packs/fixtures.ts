/**
 * A tiny pack for the pack tests: a corridor along the x axis with goals a (10,0), b (20,0) and
 * c (40,0) behind a wall at x = 30, and text-mode controllers (no Blockly needed) that drive east
 * at a speed the Top layer decides.
 */
import { parsePack, parseSubmission } from '../../../app/core/packs';
import type { Pack, Submission } from '../../../app/core/packs';
import { createInterpreterSandbox } from '../../../app/core/sandbox/interpreter';
import type { GradeOptions } from '../../../app/core/packs';

export const options: GradeOptions = { sandbox: createInterpreterSandbox, generateBody: null };

export type Json = Record<string, unknown>;

export function world(overrides: Json = {}): Json {
  return {
    format: 'layerbot-world',
    version: 1,
    name: 'Corridor',
    robot: { x: 0, y: 0, heading: 0 },
    goals: [
      { name: 'a', x: 10, y: 0 },
      { name: 'b', x: 20, y: 0 },
      { name: 'c', x: 40, y: 0 },
    ],
    plan: ['a', 'b'],
    walls: [[[30, -5], [30, 5]]],
    ...overrides,
  };
}

/** A controller: Top.speed returns `speed`; Bottom.changePos moves east by it (`move` replaces its code). */
export function controller(opts: { speed?: string; move?: string; extraLayer?: Json } = {}): Json {
  return {
    format: 'layerbot-controller',
    version: 1,
    name: 'East',
    bodyCommand: 'changePos',
    layers: [
      ...(opts.extraLayer ? [opts.extraLayer] : []),
      {
        name: 'Top',
        variables: [{ name: 'SPEED', value: 1 }],
        functions: [{ name: 'speed', output: 'number', inputs: [], body: { kind: 'text', code: opts.speed ?? 'return SPEED;' } }],
      },
      {
        name: 'Bottom',
        functions: [
          {
            name: 'changePos',
            output: 'move',
            inputs: [
              { name: 'speed', from: { kind: 'function', function: 'speed' } },
              { name: 'tick', from: { kind: 'world', input: 'tick' } },
            ],
            body: { kind: 'text', code: opts.move ?? 'return {heading: 0, dx: speed, dy: 0};' },
          },
        ],
      },
    ],
  };
}

export function challenge(overrides: Json = {}): Json {
  return {
    id: 'east',
    title: 'Drive east',
    description: 'Reach a and b.',
    world: world(),
    starter: controller({ speed: 'return 0;' }),
    locked: [{ layer: 'Bottom' }],
    criteria: [{ kind: 'reachGoals' }, { kind: 'noCrash' }],
    hints: ['Speed up.'],
    maxTicks: 100,
    ...overrides,
  };
}

export function packJson(challenges: Json[] = [challenge()]): Json {
  return { format: 'layerbot-pack', version: 1, title: 'Tiny', author: 'Tests', description: 'A tiny pack.', challenges };
}

export function pack(challenges?: Json[]): Pack {
  const parsed = parsePack(JSON.stringify(packJson(challenges), null, 2), 'tiny.pack.json');
  if (!parsed.ok) throw new Error(parsed.problems.map((p) => `${p.path}: ${p.message}`).join('\n'));
  return parsed.value;
}

export function submissionJson(controllers: Record<string, Json>, student = 'Ada'): Json {
  return { format: 'layerbot-submission', version: 1, pack: 'Tiny', student, controllers };
}

export function submission(controllers: Record<string, Json>): Submission {
  const parsed = parseSubmission(JSON.stringify(submissionJson(controllers)), 'ada.submission.json');
  if (!parsed.ok) throw new Error(parsed.problems.map((p) => `${p.path}: ${p.message}`).join('\n'));
  return parsed.value;
}
