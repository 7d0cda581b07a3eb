/**
 * The output panel: every printed line with its tick and function. Reset clears it; scrubbing
 * highlights the selected tick's lines and scrolls to them without clearing anything.
 */
import type { TickFrame } from '../engine/protocol';
import { el } from './dom';

/** Lines kept in the page at most: a print in every tick of a long run would otherwise pile up. */
const MAX_LINES = 5000;

export class OutputPanel {
  private lines: HTMLElement[] = [];
  private count = 0;
  private highlighted: HTMLElement[] = [];
  private highlightedTick = -1;
  private byTick = new Map<number, HTMLElement[]>();
  private readonly list = el('div', 'out-list');
  private readonly placeholder = el('div', 'empty-state');

  constructor(
    private readonly root: HTMLElement,
    private readonly badge: HTMLElement,
  ) {
    const inner = el('div');
    inner.append(el('b', undefined, 'Nothing printed yet'), 'Lines that functions print appear here with their tick.');
    this.placeholder.appendChild(inner);
    this.clear();
  }

  clear(): void {
    this.lines = [];
    this.count = 0;
    this.highlighted = [];
    this.highlightedTick = -1;
    this.byTick.clear();
    this.list.replaceChildren();
    this.root.replaceChildren(this.placeholder);
    this.badge.textContent = '';
  }

  /** Appends the lines printed in `frames`. */
  append(frames: readonly TickFrame[]): void {
    const frag = document.createDocumentFragment();
    for (const f of frames) {
      for (const line of f.printed) {
        const row = el('div', 'out-line');
        row.dataset.tick = String(f.tick);
        row.append(el('span', 't', String(f.tick)), el('span', 'fn', line.function), el('span', 'text', line.text));
        row.title = `tick ${f.tick}, function ${line.function} (layer ${line.layer})`;
        this.lines.push(row);
        const same = this.byTick.get(f.tick);
        if (same) same.push(row);
        else this.byTick.set(f.tick, [row]);
        frag.appendChild(row);
        this.count++;
      }
    }
    if (!frag.childNodes.length) return;
    if (this.root.firstChild !== this.list) this.root.replaceChildren(this.list);
    const atBottom = this.root.scrollTop + this.root.clientHeight >= this.root.scrollHeight - 4;
    this.list.appendChild(frag);
    while (this.lines.length > MAX_LINES) {
      const old = this.lines.shift();
      old?.remove();
      if (old) this.byTick.delete(Number(old.dataset.tick));
    }
    this.highlightedTick = -1; // New lines may belong to the highlighted tick.
    this.badge.textContent = this.count > 999 ? '999+' : String(this.count);
    if (atBottom) this.root.scrollTop = this.root.scrollHeight;
  }

  /** Highlights the lines of `tick`; `scroll` brings them into view (when the user scrubbed). */
  highlight(tick: number, scroll: boolean): void {
    if (tick === this.highlightedTick) return;
    this.highlightedTick = tick;
    for (const h of this.highlighted) h.classList.remove('current');
    this.highlighted = this.byTick.get(tick) ?? [];
    for (const h of this.highlighted) h.classList.add('current');
    if (scroll && this.highlighted.length) this.highlighted[0].scrollIntoView({ block: 'nearest' });
  }
}
