/**
 * The world view's camera: world coordinates are mathematical (y up), the screen's are not.
 * `scale` is pixels per world unit; (cx, cy) is the world point at the centre of the view.
 */
import type { Bounds } from '../../core/world/world';

export class Camera {
  scale = 5;
  cx = 50;
  cy = 20;
  width = 1;
  height = 1;

  toScreen(x: number, y: number): { x: number; y: number } {
    return { x: this.width / 2 + (x - this.cx) * this.scale, y: this.height / 2 - (y - this.cy) * this.scale };
  }

  toWorld(sx: number, sy: number): { x: number; y: number } {
    return { x: this.cx + (sx - this.width / 2) / this.scale, y: this.cy - (sy - this.height / 2) / this.scale };
  }

  /** Shows all of `b` with a margin of `pad` pixels. */
  fit(b: Bounds, pad = 28): void {
    const w = Math.max(1, b.maxX - b.minX);
    const h = Math.max(1, b.maxY - b.minY);
    this.scale = Math.max(0.05, Math.min((this.width - 2 * pad) / w, (this.height - 2 * pad) / h));
    this.cx = (b.minX + b.maxX) / 2;
    this.cy = (b.minY + b.maxY) / 2;
  }

  /** Zooms by `factor` keeping the world point under the screen point (sx, sy) in place. */
  zoomAt(sx: number, sy: number, factor: number): void {
    const before = this.toWorld(sx, sy);
    this.scale = Math.min(400, Math.max(0.05, this.scale * factor));
    const after = this.toWorld(sx, sy);
    this.cx += before.x - after.x;
    this.cy += before.y - after.y;
  }

  panBy(dxPixels: number, dyPixels: number): void {
    this.cx -= dxPixels / this.scale;
    this.cy += dyPixels / this.scale;
  }
}
