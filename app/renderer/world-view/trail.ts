/**
 * The robot's trail as in the textbook's plots: a green dot per tick, red where the whisker
 * touched, a star where it crashed. Dots are drawn in chunks: a finished chunk is never redrawn,
 * so a long run costs one small chunk per frame.
 */
import { Container, Graphics } from 'pixi.js';
import type { TickFrame } from '../engine/protocol';
import type { Palette } from './palette';

const CHUNK = 256;
const DOT = 0.38;

export class TrailLayer {
  readonly container = new Container();
  private chunks: Graphics[] = [];
  private drawnUpTo = 0;
  private readonly crashMark = new Graphics();

  constructor(private palette: Palette) {
    this.container.addChild(this.crashMark);
  }

  setPalette(p: Palette): void {
    this.palette = p;
    this.clear();
  }

  clear(): void {
    for (const g of this.chunks) g.destroy();
    this.chunks = [];
    this.drawnUpTo = 0;
    this.crashMark.clear();
  }

  /** Draws frames[0 .. count-1]; only the chunks that gained dots are redrawn. */
  update(frames: readonly TickFrame[], count: number, robotSize: number): void {
    if (count === 0) return this.clear();
    if (count < this.drawnUpTo) this.truncate(count);
    if (count === this.drawnUpTo) return;
    const first = Math.floor(this.drawnUpTo / CHUNK);
    const last = Math.floor((count - 1) / CHUNK);
    for (let c = first; c <= last; c++) this.drawChunk(c, frames, Math.min(count, (c + 1) * CHUNK));
    this.drawnUpTo = count;
    const crash = frames[count - 1]?.crash;
    this.crashMark.clear();
    if (crash) {
      this.crashMark
        .star(crash.point[0], crash.point[1], 5, robotSize * 0.9, robotSize * 0.4)
        .fill({ color: this.palette.crash })
        .stroke({ color: this.palette.robotEdge, width: robotSize * 0.08 });
      this.container.addChild(this.crashMark); // Keep the star above the dots.
    }
  }

  /** Drops the dots from `count` on: later chunks go, the chunk holding `count - 1` is redrawn. */
  private truncate(count: number): void {
    const keep = Math.floor((count - 1) / CHUNK);
    for (const g of this.chunks.splice(keep + 1)) g.destroy();
    this.drawnUpTo = keep * CHUNK;
  }

  private drawChunk(c: number, frames: readonly TickFrame[], end: number): void {
    let g = this.chunks[c];
    if (!g) {
      g = new Graphics();
      this.chunks[c] = g;
      this.container.addChildAt(g, c);
    }
    g.clear();
    const start = c * CHUNK;
    // Two passes, one fill each: far fewer draw batches than alternating colours.
    for (let i = start; i < end; i++) if (!frames[i].whisker) g.circle(frames[i].x, frames[i].y, DOT);
    g.fill({ color: this.palette.trail });
    for (let i = start; i < end; i++) if (frames[i].whisker) g.circle(frames[i].x, frames[i].y, DOT);
    g.fill({ color: this.palette.trailTouch });
  }
}
