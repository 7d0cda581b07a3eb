/**
 * The robot's trail as in the textbook's plots: a green dot per tick, red where the whisker
 * touched, a star where it crashed. Dots are particles (one textured quad each, not a tessellated
 * circle), held in chunks: a finished chunk is never touched again, so a long run costs one small
 * upload per frame, and drawing ten thousand dots stays cheap even without a GPU.
 */
import { Container, Graphics, Particle, ParticleContainer, Texture } from 'pixi.js';
import type { TickFrame } from '../engine/protocol';
import type { Palette } from './palette';

const CHUNK = 512;
/** The dot's radius in world units. */
const DOT = 0.38;
/** The dot texture's size in pixels: large enough to stay round when zoomed in. */
const TEXTURE_SIZE = 64;

let dotTexture: Texture | null = null;

/** A white disc, tinted per dot. */
function dot(): Texture {
  if (dotTexture) return dotTexture;
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = TEXTURE_SIZE;
  const ctx = canvas.getContext('2d')!;
  ctx.fillStyle = '#ffffff';
  ctx.beginPath();
  ctx.arc(TEXTURE_SIZE / 2, TEXTURE_SIZE / 2, TEXTURE_SIZE / 2 - 1, 0, Math.PI * 2);
  ctx.fill();
  dotTexture = Texture.from(canvas);
  return dotTexture;
}

export class TrailLayer {
  readonly container = new Container();
  private chunks: ParticleContainer[] = [];
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
    for (const c of this.chunks) c.destroy();
    this.chunks = [];
    this.drawnUpTo = 0;
    this.crashMark.clear();
  }

  /** Draws frames[0 .. count-1]; only the newest dots are added. */
  update(frames: readonly TickFrame[], count: number, robotSize: number): void {
    if (count === 0) return this.clear();
    if (count < this.drawnUpTo) this.truncate(count);
    if (count === this.drawnUpTo) return;
    for (let i = this.drawnUpTo; i < count; ) {
      const c = Math.floor(i / CHUNK);
      const end = Math.min(count, (c + 1) * CHUNK);
      this.addDots(c, frames, i, end);
      i = end;
    }
    this.drawnUpTo = count;
    const crash = frames[count - 1]?.crash;
    this.crashMark.clear();
    if (crash) {
      this.crashMark
        .star(crash.point[0], crash.point[1], 5, robotSize * 0.9, robotSize * 0.4)
        .fill({ color: this.palette.crash })
        .stroke({ color: this.palette.robotEdge, width: robotSize * 0.08 });
    }
  }

  /** Drops the dots from `count` on. */
  private truncate(count: number): void {
    const keep = Math.floor((count - 1) / CHUNK);
    for (const c of this.chunks.splice(keep + 1)) c.destroy();
    const last = this.chunks[keep];
    if (last) {
      last.removeParticles(count - keep * CHUNK);
      last.update();
    }
    this.drawnUpTo = count;
  }

  private addDots(c: number, frames: readonly TickFrame[], start: number, end: number): void {
    let chunk = this.chunks[c];
    if (!chunk) {
      chunk = new ParticleContainer({ texture: dot(), dynamicProperties: { position: false, vertex: false, rotation: false, uvs: false, color: false } });
      this.chunks[c] = chunk;
      // Below the crash star.
      this.container.addChildAt(chunk, this.container.children.length - 1);
    }
    const scale = (DOT * 2) / TEXTURE_SIZE;
    const texture = dot();
    for (let i = start; i < end; i++) {
      const f = frames[i];
      chunk.addParticle(new Particle({ texture, x: f.x, y: f.y, scaleX: scale, scaleY: scale, anchorX: 0.5, anchorY: 0.5, tint: f.whisker ? this.palette.trailTouch : this.palette.trail }));
    }
    chunk.update();
  }
}
