/**
 * The grading Worker: runs a challenge (its world and every hidden variant) on the student's
 * controller and judges it, off the page's thread, so the page keeps drawing during a Check.
 * The same Session and sandbox (JS-Interpreter) as the engine Worker and `layerbot grade`;
 * block code comes from the page (Blockly needs a DOM), as for the engine (engine/bodies.ts).
 */
import { gradeChallenge } from '../../core/packs/grade';
import { createInterpreterSandbox } from '../../core/sandbox/interpreter';
import { tableGenerator } from '../engine/bodies';
import type { GradeAnswer, GradeRequest } from './grade-protocol';

// Typed by shape, so this file compiles with the page's DOM types as well as in a Worker.
const scope = self as unknown as { onmessage: ((e: MessageEvent<GradeRequest>) => void) | null; postMessage(message: GradeAnswer): void };

scope.onmessage = (e) => {
  const msg = e.data;
  if (msg?.type !== 'grade') return;
  const t0 = performance.now();
  try {
    const verdict = gradeChallenge(msg.challenge, msg.controller, { sandbox: createInterpreterSandbox, generateBody: tableGenerator(msg.bodies) });
    scope.postMessage({ type: 'verdict', id: msg.id, verdict, ms: performance.now() - t0 });
  } catch (err) {
    scope.postMessage({ type: 'failed', id: msg.id, message: err instanceof Error ? err.message : String(err) });
  }
};
