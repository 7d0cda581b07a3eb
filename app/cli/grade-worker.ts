/**
 * A worker thread of `layerbot grade`: reads the pack once, then grades submission files one at a
 * time with the reference engine (JS-Interpreter), the same Session as the app.
 */
import { parentPort } from 'node:worker_threads';
import { generateBody } from '../../blocks/generate';
import { formatProblems } from '../core/formats';
import type { GradeOptions, Pack } from '../core/packs';
import { parsePack } from '../core/packs';
import { createInterpreterSandbox } from '../core/sandbox/interpreter';
import type { GradeInit, GradeReply, GradeTask } from './grade-protocol';
import { gradeFile } from './grade-submission';

let pack: Pack | null = null;
let options: GradeOptions | null = null;

function reply(message: GradeReply): void {
  parentPort?.postMessage(message);
}

parentPort?.on('message', (msg: GradeInit | GradeTask) => {
  if (msg.type === 'init') {
    const parsed = parsePack(msg.packText, msg.packFile);
    if (!parsed.ok) return reply({ type: 'failed', message: formatProblems(parsed.problems) });
    pack = parsed.value;
    options = {
      sandbox: createInterpreterSandbox,
      generateBody,
      ...(msg.seed !== undefined ? { seed: msg.seed } : {}),
      ...(msg.maxStepBudget !== undefined ? { maxStepBudget: msg.maxStepBudget } : {}),
    };
    return reply({ type: 'ready' });
  }
  if (!pack || !options) return reply({ type: 'failed', message: 'the worker got a submission before the pack' });
  reply({ type: 'verdict', index: msg.index, verdict: gradeFile(pack, msg.file, options) });
});
