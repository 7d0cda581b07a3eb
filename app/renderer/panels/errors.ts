/**
 * The errors panel: the error that stopped the run (function, layer, tick, message) and problems
 * loading the controller. "Show block" hands the error to the editor through `reveal`.
 */
import type { ControllerError } from '../../core/session/types';
import { el } from './dom';

export class ErrorsPanel {
  private runError: ControllerError | null = null;
  private problems: string[] = [];

  constructor(
    private readonly root: HTMLElement,
    private readonly badge: HTMLElement,
    private readonly reveal: (error: ControllerError) => void,
  ) {
    this.render();
  }

  setRunError(error: ControllerError | null): void {
    if (error === this.runError) return;
    this.runError = error;
    this.render();
  }

  addProblem(message: string): void {
    this.problems.push(message);
    this.render();
  }

  clearProblems(): void {
    if (!this.problems.length) return;
    this.problems = [];
    this.render();
  }

  get count(): number {
    return this.problems.length + (this.runError ? 1 : 0);
  }

  private render(): void {
    this.badge.textContent = this.count ? String(this.count) : '';
    if (!this.count) {
      const box = el('div', 'empty-state');
      const inner = el('div');
      inner.append(el('b', undefined, 'No errors'), 'When a function fails, you will see where and why here.');
      box.appendChild(inner);
      this.root.replaceChildren(box);
      return;
    }
    const items: HTMLElement[] = [];
    const e = this.runError;
    if (e) {
      const item = el('div', 'err-item');
      item.dataset.tick = String(e.tick);
      const where = el('div', 'where', e.function ? `Function “${e.function}”` : 'Controller');
      const meta = el('div', 'meta', `${e.layer ? `layer ${e.layer} · ` : ''}tick ${e.tick}`);
      const msg = el('div', 'msg', e.message);
      const btn = el('button', 'small', 'Show block');
      btn.disabled = !e.function;
      btn.addEventListener('click', () => this.reveal(e));
      item.append(where, meta, btn, msg);
      items.push(item);
    }
    for (const p of this.problems) {
      const item = el('div', 'err-item');
      item.append(el('div', 'where', 'The controller cannot run'), el('div'), el('div', 'msg', p));
      items.push(item);
    }
    this.root.replaceChildren(...items);
  }
}
