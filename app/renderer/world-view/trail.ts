/**
 * The robot's trail as in the textbook's plots: a green dot per tick, red where the whisker
 * touched, a star where it crashed. Dots are particles (one textured quad each, not a tessellated
 * circle), held in chunks. Full chunks live in `finished`, which the view bakes into its backdrop
 * texture (redrawn only when a chunk fills up or the trail is cut back); the chunk being filled and
 * the crash star live in `live`, drawn every frame. A frame costs the same however long the run.
 * The canvas renderer draws chunks as Graphics (its particles do not render into textures).
 */
import { Container, Graphics, Particle, ParticleContainer, Texture } from 'pixi.js';
import type { TickFrame } from '../engine/protocol';
import type { Palette } from './palette';

const CHUNK = 256;
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

/** A run of at most CHUNK dots. */
interface Chunk {
  readonly view: Container;
  /** Adds the dots of frames[start .. end-1] (the chunk's dots so far run up to start). */
  add(frames: readonly TickFrame[], start: number, end: number, palette: Palette): void;
  /** Keeps the first `n` dots. */
  cut(n: number, palette: Palette): void;
}

/** Dots as particles: one textured quad each (WebGL). */
class ParticleChunk implements Chunk {
  readonly view = new ParticleContainer({ texture: dot(), dynamicProperties: { position: false, vertex: false, rotation: false, uvs: false, color: false } });

  add(frames: readonly TickFrame[], start: number, end: number, palette: Palette): void {
    const scale = (DOT * 2) / TEXTURE_SIZE;
    const texture = dot();
    for (let i = start; i < end; i++) {
      const f = frames[i];
      this.view.addParticle(new Particle({ texture, x: f.x, y: f.y, scaleX: scale, scaleY: scale, anchorX: 0.5, anchorY: 0.5, tint: f.whisker ? palette.trailTouch : palette.trail }));
    }
    this.view.update();
  }

  cut(n: number): void {
    this.view.removeParticles(n);
    this.view.update();
  }
}

/** Dots as circles in one Graphics, redrawn whole when dots are added (canvas). */
class GraphicsChunk implements Chunk {
  readonly view = new Graphics();
  private frames: readonly TickFrame[] = [];
  private first = -1;
  private end = 0;

  add(frames: readonly TickFrame[], start: number, end: number, palette: Palette): void {
    if (this.first < 0) this.first = start;
    this.frames = frames;
    this.end = end;
    this.draw(palette);
  }

  cut(n: number, palette: Palette): void {
    this.end = this.first + n;
    this.draw(palette);
  }

  private draw(palette: Palette): void {
    const g = this.view.clear();
    // Two passes, one fill each: far fewer draw batches than alternating colours.
    for (let i = this.first; i < this.end; i++) if (!this.frames[i].whisker) g.circle(this.frames[i].x, this.frames[i].y, DOT);
    g.fill({ color: palette.trail });
    for (let i = this.first; i < this.end; i++) if (this.frames[i].whisker) g.circle(this.frames[i].x, this.frames[i].y, DOT);
    g.fill({ color: palette.trailTouch });
  }
}

export class TrailLayer {
  /** Full chunks: drawn into the view's backdrop. */
  readonly finished = new Container();
  /** The chunk being filled and the crash star: drawn every frame. */
  readonly live = new Container();
  private chunks: Chunk[] = [];
  private drawnUpTo = 0;
  private readonly crashMark = new Graphics();
  /** Set when `finished` lost chunks (or changed colours): the view re-renders its whole backdrop. */
  finishedChanged = false;
  /** Chunks that filled up since the view last looked: it draws just these onto its backdrop. */
  readonly newlyFinished: Container[] = [];

  constructor(
    private palette: Palette,
    private readonly particles: boolean,
  ) {
    this.live.addChild(this.crashMark);
  }

  setPalette(p: Palette): void {
    this.palette = p;
    this.clear();
  }

  clear(): void {
    if (this.finished.children.length > 0) this.finishedChanged = true;
    for (const c of this.chunks) c.view.destroy();
    this.chunks = [];
    this.newlyFinished.length = 0;
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

  /** Drops the dots from `count` on: the chunk holding the last dot kept becomes the live one. */
  private truncate(count: number): void {
    const keep = Math.floor((count - 1) / CHUNK);
    for (const c of this.chunks.splice(keep + 1)) c.view.destroy();
    const last = this.chunks[keep];
    if (last) {
      last.cut(count - keep * CHUNK, this.palette);
      if (last.view.parent !== this.live) this.live.addChildAt(last.view, 0);
    }
    this.newlyFinished.length = 0;
    this.finishedChanged = true;
    this.drawnUpTo = count;
  }

  private addDots(c: number, frames: readonly TickFrame[], start: number, end: number): void {
    let chunk = this.chunks[c];
    if (!chunk) {
      chunk = this.particles ? new ParticleChunk() : new GraphicsChunk();
      this.chunks[c] = chunk;
      this.live.addChildAt(chunk.view, 0); // Below the crash star.
    }
    chunk.add(frames, start, end, this.palette);
    if (end === (c + 1) * CHUNK) {
      this.finished.addChild(chunk.view);
      this.newlyFinished.push(chunk.view);
    }
  }
}
