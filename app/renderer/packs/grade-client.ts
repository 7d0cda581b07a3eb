/**
 * The page's side of grading: one grading Worker, one Check at a time. A new Check while one is
 * running ends the old Worker (its answer would be stale) and starts afresh; a Check that takes
 * longer than the limit is stopped and answered with a failed verdict, never left hanging.
 */
import { generateBody } from '../../../blocks/generate';
import type { ControllerSpec } from '../../core/controller/model';
import type { Challenge, ChallengeVerdict } from '../../core/packs/model';
import { generateBodies } from '../engine/bodies';
import type { GradeAnswer, GradeRequest } from './grade-protocol';

/** The longest a Check may take before it is stopped. */
const LIMIT_MS = 120_000;

export interface CheckResult {
  readonly verdict: ChallengeVerdict;
  /** Wall time from Check to verdict, block generation included. */
  readonly ms: number;
}

export class GradeClient {
  private worker: Worker | null = null;
  private nextId = 1;
  private pending: { id: number; resolve: (r: CheckResult | null) => void; timer: ReturnType<typeof setTimeout>; t0: number; challenge: Challenge } | null = null;

  /** True while a Check runs. */
  get busy(): boolean {
    return this.pending !== null;
  }

  /** Grades `controller` on `challenge`; null when a newer Check replaced this one. */
  check(challenge: Challenge, controller: ControllerSpec): Promise<CheckResult | null> {
    const t0 = performance.now();
    if (this.pending) this.cancel();
    const id = this.nextId++;
    const bodies = generateBodies(controller, generateBody);
    const worker = this.ensureWorker();
    return new Promise((resolve) => {
      const timer = setTimeout(() => this.fail(id, `the check was stopped after ${LIMIT_MS / 1000} s`), LIMIT_MS);
      this.pending = { id, resolve, timer, t0, challenge };
      const request: GradeRequest = { type: 'grade', id, challenge, controller, bodies };
      worker.postMessage(request);
    });
  }

  /** Stops the running Check (its promise resolves to null). */
  cancel(): void {
    const p = this.pending;
    if (!p) return;
    this.pending = null;
    clearTimeout(p.timer);
    this.worker?.terminate();
    this.worker = null;
    p.resolve(null);
  }

  private ensureWorker(): Worker {
    if (this.worker) return this.worker;
    const worker = new Worker(new URL('./grade-worker.ts', import.meta.url), { type: 'module', name: 'layerbot-grader' });
    worker.onmessage = (e: MessageEvent<GradeAnswer>) => this.receive(e.data);
    worker.onerror = (e) => {
      if (this.pending) this.fail(this.pending.id, `the grader stopped unexpectedly: ${e.message || 'unknown error'}`);
    };
    this.worker = worker;
    return worker;
  }

  private receive(a: GradeAnswer): void {
    const p = this.pending;
    if (!p || a.id !== p.id) return;
    if (a.type === 'failed') return this.fail(a.id, a.message);
    this.pending = null;
    clearTimeout(p.timer);
    p.resolve({ verdict: a.verdict, ms: performance.now() - p.t0 });
  }

  /** Answers the Check with a failed verdict that says why, and starts a fresh Worker next time. */
  private fail(id: number, message: string): void {
    const p = this.pending;
    if (!p || p.id !== id) return;
    this.pending = null;
    clearTimeout(p.timer);
    this.worker?.terminate();
    this.worker = null;
    const c = p.challenge;
    p.resolve({
      verdict: { challenge: c.id, title: c.title, passed: false, reasons: [{ criterion: 'the check finishes', passed: false, detail: message }] },
      ms: performance.now() - p.t0,
    });
  }
}
