/** The arc table: every arc at the selected tick (from, to, input, value, changed since the tick before). */
import type { ArcRow } from '../engine/client';
import { el } from './dom';
import { shortValue } from './format';

export class ArcTable {
  constructor(private readonly root: HTMLElement) {
    this.empty('No controller is running', 'Open a controller to see the values on its arcs.');
  }

  empty(title: string, text: string): void {
    const box = el('div', 'empty-state');
    const inner = el('div');
    inner.append(el('b', undefined, title), text);
    box.appendChild(inner);
    this.root.replaceChildren(box);
  }

  show(tick: number, rows: readonly ArcRow[]): void {
    if (rows.length === 0) return this.empty('No arcs', 'This controller has no inputs to show.');
    if (tick === 0) return this.empty('Tick 0 is the start', 'No function has run yet. Step once to see every arc’s value.');
    const table = el('table', 'arcs');
    table.dataset.tick = String(tick);
    const head = el('tr');
    for (const h of ['From', 'To', 'Input', 'Value', 'Changed']) head.appendChild(el('th', `c-${h.toLowerCase()}`, h));
    table.appendChild(el('thead')).appendChild(head);
    const body = el('tbody');
    for (const r of rows) {
      const tr = el('tr', r.changed ? 'changed' : undefined);
      const from = el('td', 'from', r.from.replace(/^previous\./, ''));
      if (r.previousTick) from.appendChild(el('span', 'prev', 'previous tick'));
      const value = el('td', 'value', shortValue(r.value));
      value.title = shortValue(r.value);
      const to = el('td', 'to');
      // The debugger (debugger/index.ts) handles these clicks: it replays the function at this tick.
      const step = el('button', 'step-into');
      step.dataset.stepInto = r.to;
      step.title = `Step into ${r.to}: replay it at tick ${tick}, block by block`;
      step.setAttribute('aria-label', `Step into ${r.to}`);
      step.innerHTML = '<svg viewBox="0 0 24 24" aria-hidden="true"><path d="M6 5v14l9-7z M17 5h2v14h-2z"/></svg>';
      to.append(step, r.to);
      tr.append(from, to, el('td', 'input', r.input), value, el('td', 'changed-cell', r.changed ? 'changed' : ''));
      body.appendChild(tr);
    }
    table.appendChild(body);
    this.root.replaceChildren(table);
  }
}
