/**
 * Chooses a grid-shaped arc value to lay over the world. The candidates are found among the arcs
 * of the selected tick; the grid's placement is the grid record found among the same tick's arcs.
 */
import type { GridSpec } from '../../core/sandbox/api';
import type { ArcRow } from '../engine/client';
import type { GridField, OverlayKind } from '../world-view/overlay';
import { gridField, isGridSpec } from '../world-view/overlay';
import { byId, el } from './dom';

export interface OverlayChoice {
  readonly value: unknown;
  readonly field: GridField;
  readonly grid: GridSpec;
  readonly kind: OverlayKind;
}

export class OverlayPicker {
  private readonly select = byId<HTMLSelectElement>('overlay-select');
  private readonly hint = byId('overlay-hint');
  private kind: OverlayKind = 'heat';
  private wanted = '';
  private fields = new Map<unknown, GridField | null>();

  constructor(private readonly changed: () => void) {
    this.select.addEventListener('change', () => {
      this.wanted = this.select.value;
      this.changed();
    });
    for (const b of byId('overlay-kind').querySelectorAll<HTMLButtonElement>('[data-kind]')) {
      b.addEventListener('click', () => {
        this.kind = b.dataset.kind as OverlayKind;
        for (const o of byId('overlay-kind').querySelectorAll('[data-kind]')) o.setAttribute('aria-pressed', String(o === b));
        this.changed();
      });
    }
    this.update([]);
  }

  /** The grid value of `v`, cached by identity (values are immutable and shared across ticks). */
  private field(v: unknown): GridField | null {
    if (!this.fields.has(v)) {
      if (this.fields.size > 64) this.fields.clear();
      this.fields.set(v, gridField(v));
    }
    return this.fields.get(v) ?? null;
  }

  /** Refreshes the choices from a tick's arcs and returns what to draw, or null. */
  update(rows: readonly ArcRow[]): OverlayChoice | null {
    const sources = new Map<string, unknown>();
    // World inputs (walls are lists of point pairs) are never grids worth drawing.
    for (const r of rows) if (!r.from.startsWith('world.') && !sources.has(r.from) && this.field(r.value)) sources.set(r.from, r.value);
    const grids = rows.map((r) => r.value).filter(isGridSpec);
    const names = [...sources.keys()];
    const current = [...this.select.options].map((o) => o.value).join('\n');
    if (current !== ['', ...names].join('\n')) {
      const none = el('option', undefined, sources.size ? 'None' : 'No grid values at this tick');
      none.value = '';
      this.select.replaceChildren(none, ...names.map((n) => {
        const o = el('option', undefined, n.replace(/^previous\./, '') + (n.startsWith('previous.') ? ' (previous tick)' : ''));
        o.value = n;
        return o;
      }));
    }
    this.select.value = sources.has(this.wanted) ? this.wanted : '';
    if (!this.wanted || !sources.has(this.wanted)) {
      this.hint.textContent = sources.size ? 'Lay a grid value over the world.' : 'Grid-shaped values (like value iteration’s) can be shown over the world.';
      return null;
    }
    const value = sources.get(this.wanted);
    const field = this.field(value) as GridField;
    const grid = grids.find((g) => g.cols === field.cols && g.rows === field.rows);
    if (!grid) {
      this.hint.textContent = 'No grid record of that size at this tick: cannot place it.';
      return null;
    }
    this.hint.textContent = this.kind === 'arrows' && !field.actions ? 'These values are not actions: showing nothing. Try the heat map.' : `${field.cols} × ${field.rows} cells of size ${grid.cell}.`;
    return { value, field, grid, kind: this.kind };
  }
}
