/**
 * Grid overlays: an arc value shaped like a grid (rows of numbers, rows of actions, or rows of
 * per-action Q-values) drawn over the world as a heat map or as policy arrows, placed by the grid
 * record `{x0, y0, cell, cols, rows}` (app/core/sandbox/api.ts `makeGrid`).
 */
import { Container, Graphics, Sprite, Texture } from 'pixi.js';
import type { GridSpec } from '../../core/sandbox/api';

export type OverlayKind = 'heat' | 'arrows';

/** A grid-shaped value reduced to numbers per cell: values for the heat map, actions for arrows. */
export interface GridField {
  readonly rows: number;
  readonly cols: number;
  /** Row-major, row 0 first (row 0 is at the grid's y0: the bottom). */
  readonly values: Float64Array;
  /** Action per cell (0 N, 1 E, 2 S, 3 W, 4 stay), or null when the value holds no actions. */
  readonly actions: Int8Array | null;
}

const isNum = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);

/** Reads a grid-shaped value, or returns null when it is not one. */
export function gridField(value: unknown): GridField | null {
  if (!Array.isArray(value) || value.length === 0 || !Array.isArray(value[0])) return null;
  const rows = value.length;
  const cols = (value[0] as unknown[]).length;
  if (cols === 0) return null;
  const values = new Float64Array(rows * cols);
  let actions: Int8Array | null = new Int8Array(rows * cols);
  const q = Array.isArray((value[0] as unknown[])[0]);
  for (let r = 0; r < rows; r++) {
    const row = value[r] as unknown;
    if (!Array.isArray(row) || row.length !== cols) return null;
    for (let c = 0; c < cols; c++) {
      const cell: unknown = row[c];
      if (q) {
        if (!Array.isArray(cell) || cell.length === 0 || !cell.every(isNum)) return null;
        let best = 0;
        for (let a = 1; a < cell.length; a++) if ((cell[a] as number) > (cell[best] as number)) best = a;
        values[r * cols + c] = cell[best] as number;
        if (actions) actions[r * cols + c] = best;
      } else {
        if (!isNum(cell)) return null;
        values[r * cols + c] = cell;
        if (actions && (!Number.isInteger(cell) || cell < 0 || cell > 4)) actions = null;
        else if (actions) actions[r * cols + c] = cell;
      }
    }
  }
  return { rows, cols, values, actions };
}

/** True when `v` is a grid record. */
export function isGridSpec(v: unknown): v is GridSpec {
  if (typeof v !== 'object' || v === null) return false;
  const g = v as Record<string, unknown>;
  return isNum(g.x0) && isNum(g.y0) && isNum(g.cell) && g.cell > 0 && isNum(g.cols) && isNum(g.rows);
}

/** Colour ramp from cool (low) to warm (high): a perceptually even viridis-like ramp. */
const RAMP = [
  [68, 1, 84],
  [59, 82, 139],
  [33, 145, 140],
  [94, 201, 98],
  [253, 231, 37],
];

function ramp(t: number): [number, number, number] {
  const x = Math.min(1, Math.max(0, t)) * (RAMP.length - 1);
  const i = Math.min(RAMP.length - 2, Math.floor(x));
  const f = x - i;
  const a = RAMP[i];
  const b = RAMP[i + 1];
  return [a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, a[2] + (b[2] - a[2]) * f];
}

export class OverlayLayer {
  readonly container = new Container();
  private sprite: Sprite | null = null;
  private readonly arrows = new Graphics();
  private key: unknown = null;
  /** Counts the changes of what the layer shows (the view re-renders its backdrop when it moves). */
  version = 0;

  constructor() {
    this.container.addChild(this.arrows);
  }

  clear(): void {
    if (this.key !== null || this.sprite || this.arrows.context.instructions.length) this.version++;
    this.key = null;
    this.sprite?.destroy({ texture: true, textureSource: true });
    this.sprite = null;
    this.arrows.clear();
  }

  /** Draws `field` over `grid`; does nothing when the same value is shown the same way. */
  show(value: unknown, field: GridField, grid: GridSpec, kind: OverlayKind, arrowColor: number): void {
    if (this.key === value && this.kindShown === kind) return;
    this.clear();
    this.version++;
    this.key = value;
    this.kindShown = kind;
    if (kind === 'heat') this.heat(field, grid);
    else if (field.actions) this.drawArrows(field, grid, arrowColor);
  }

  private kindShown: OverlayKind | null = null;

  private heat(field: GridField, grid: GridSpec): void {
    let lo = Infinity;
    let hi = -Infinity;
    for (const v of field.values) {
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
    const span = hi - lo || 1;
    const canvas = document.createElement('canvas');
    canvas.width = field.cols;
    canvas.height = field.rows;
    const ctx = canvas.getContext('2d') as CanvasRenderingContext2D;
    const img = ctx.createImageData(field.cols, field.rows);
    for (let i = 0; i < field.values.length; i++) {
      const [r, g, b] = ramp((field.values[i] - lo) / span);
      img.data[i * 4] = r;
      img.data[i * 4 + 1] = g;
      img.data[i * 4 + 2] = b;
      img.data[i * 4 + 3] = 150;
    }
    ctx.putImageData(img, 0, 0);
    const texture = Texture.from(canvas);
    texture.source.scaleMode = 'nearest';
    const sprite = new Sprite(texture);
    sprite.position.set(grid.x0, grid.y0);
    sprite.width = field.cols * grid.cell;
    sprite.height = field.rows * grid.cell;
    this.sprite = sprite;
    this.container.addChildAt(sprite, 0);
  }

  private drawArrows(field: GridField, grid: GridSpec, color: number): void {
    const actions = field.actions as Int8Array;
    if (field.rows * field.cols > 40_000) return; // Too many to read; the heat map still works.
    const g = this.arrows;
    const s = grid.cell * 0.38;
    const dirs: readonly [number, number][] = [[0, 1], [1, 0], [0, -1], [-1, 0]];
    for (let r = 0; r < field.rows; r++) {
      for (let c = 0; c < field.cols; c++) {
        const a = actions[r * field.cols + c];
        const cx = grid.x0 + (c + 0.5) * grid.cell;
        const cy = grid.y0 + (r + 0.5) * grid.cell;
        if (a === 4 || a < 0 || a > 4) {
          g.circle(cx, cy, s * 0.25);
          continue;
        }
        const [dx, dy] = dirs[a];
        const tipX = cx + dx * s;
        const tipY = cy + dy * s;
        g.moveTo(cx - dx * s, cy - dy * s).lineTo(tipX, tipY);
        g.moveTo(tipX - dx * s * 0.5 + dy * s * 0.4, tipY - dy * s * 0.5 - dx * s * 0.4)
          .lineTo(tipX, tipY)
          .lineTo(tipX - dx * s * 0.5 - dy * s * 0.4, tipY - dy * s * 0.5 + dx * s * 0.4);
      }
    }
    g.stroke({ color, width: grid.cell * 0.08, cap: 'round', join: 'round' });
  }
}
