/**
 * The world view: PixiJS draws the walls, the goals (the plan's next one highlighted), the robot
 * with its whisker, the trail, grid overlays and the Create tools' marks. The view only draws what
 * it is given; it renders on animation frames and only when something changed.
 *
 * What changes only with the camera, the walls or the overlay (grid, overlay, walls and the
 * trail's full chunks) is the backdrop: rendered once into a texture the size of the canvas, then
 * drawn each frame as one quad under the newest dots, the goals, the robot and the marks. A frame
 * while the robot runs costs a handful of draws however many walls and ticks there are.
 *
 * Where WebGL runs in software (no GPU, as on many school lab machines and in headless browsers),
 * Pixi's canvas renderer draws this scene several times faster, so the view uses it there.
 */
import 'pixi.js/unsafe-eval'; // Pixi's shader code without `new Function`: the CSP forbids eval.
import { Application, Container, Graphics, Matrix, RenderTexture, Sprite, Text } from 'pixi.js';
import type { Bounds } from '../../core/world/world';
import { whiskerSegment } from '../../core/world/world';
import type { TickFrame } from '../engine/protocol';
import { Camera } from './camera';
import { OverlayLayer } from './overlay';
import type { Palette } from './palette';
import { readPalette } from './palette';
import type { WorldPicture } from './picture';
import { nextGoalName } from './picture';
import { TrailLayer } from './trail';

/** Marks the Create tools ask the view to draw (selection, handles, a wall being drawn). */
export interface EditMarks {
  readonly selectedWall: number | null;
  readonly selectedGoal: string | null;
  readonly robotSelected: boolean;
  /** A wall or heading line being drawn. */
  readonly preview: readonly [number, number, number, number] | null;
  readonly handles: readonly (readonly [number, number])[];
}

/** WebGL with a GPU, else canvas; the page address can ask for one (`?renderer=webgl`). */
function rendererPreference(): 'webgl' | 'canvas' {
  const asked = new URLSearchParams(location.search).get('renderer');
  if (asked === 'webgl' || asked === 'canvas') return asked;
  return softwareWebGL() ? 'canvas' : 'webgl';
}

/** True when WebGL would run on the CPU (SwiftShader, llvmpipe): no GPU to draw with. */
function softwareWebGL(): boolean {
  try {
    const gl = document.createElement('canvas').getContext('webgl');
    if (!gl) return true;
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    const name = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : '';
    gl.getExtension('WEBGL_lose_context')?.loseContext();
    return /swiftshader|llvmpipe|softpipe|software/i.test(name);
  } catch {
    return false;
  }
}

const NO_MARKS: EditMarks = { selectedWall: null, selectedGoal: null, robotSelected: false, preview: null, handles: [] };

export class WorldView {
  readonly camera = new Camera();
  readonly app = new Application();
  private readonly scene = new Container();
  private readonly grid = new Graphics();
  readonly overlay = new OverlayLayer();
  private readonly walls = new Graphics();
  private readonly goals = new Graphics();
  private trail!: TrailLayer;
  private readonly robot = new Graphics();
  private readonly marks = new Graphics();
  private readonly labels = new Container();
  /** Grid, overlay, walls, goals and labels, in the camera's frame (rendered into the texture below). */
  private readonly backdrop = new Container();
  private readonly backdropScene = new Container();
  private backdropTexture!: RenderTexture;
  private backdropDirty = true;
  private overlayVersion = -1;
  private palette!: Palette;
  private picture: WorldPicture | null = null;
  private editMarks: EditMarks = NO_MARKS;
  private dirty = true;
  private cameraDirty = true;
  private goalsDirty = true;
  private showTrail = true;
  private labelTexts = new Map<string, Text>();
  /** Called once per animation frame before drawing: the app applies queued updates here. */
  beforeFrame: (() => void) | null = null;
  /** Animation frames per second, measured over the last second (for the status line and tests). */
  fps = 0;
  /** The renderer drawing the view: 'webgl' or 'canvas'. */
  rendererName = '';
  private frameCount = 0;
  private fpsSince = 0;

  constructor(private readonly host: HTMLElement) {}

  async init(): Promise<void> {
    this.palette = readPalette(this.host);
    await this.app.init({
      resizeTo: this.host,
      preference: rendererPreference(),
      antialias: true,
      autoDensity: true,
      resolution: Math.min(2, window.devicePixelRatio || 1),
      background: this.palette.background,
      autoStart: false,
      // Lets tests and screenshots read the pixels after the frame is presented.
      preserveDrawingBuffer: true,
    });
    this.app.ticker.stop();
    this.rendererName = this.app.renderer.name;
    this.app.canvas.setAttribute('aria-label', 'World view');
    this.app.canvas.classList.add('world-canvas');
    this.host.appendChild(this.app.canvas);
    this.trail = new TrailLayer(this.palette, this.rendererName === 'webgl');
    this.backdropScene.addChild(this.overlay.container, this.walls, this.trail.finished);
    this.backdrop.addChild(this.grid, this.backdropScene);
    this.backdropTexture = RenderTexture.create({ width: 1, height: 1, resolution: this.app.renderer.resolution, antialias: true });
    this.scene.addChild(this.trail.live, this.goals, this.robot, this.marks);
    this.app.stage.addChild(new Sprite(this.backdropTexture), this.scene, this.labels);
    new ResizeObserver(() => this.resized()).observe(this.host);
    this.resized();
    const loop = (t: number): void => {
      // Schedule first: one failed frame must not stop the drawing for good.
      requestAnimationFrame(loop);
      this.frame(t);
    };
    requestAnimationFrame(loop);
  }

  /** Re-reads the theme's colours. */
  refreshPalette(): void {
    this.palette = readPalette(this.host);
    this.app.renderer.background.color = this.palette.background;
    this.trail.setPalette(this.palette);
    this.trailFrames = null;
    this.cameraDirty = true;
    this.invalidate();
  }

  /** The theme's colours as the view uses them. */
  get colors(): Palette {
    return this.palette;
  }

  invalidate(): void {
    this.dirty = true;
  }

  setPicture(p: WorldPicture): void {
    if (p === this.picture) return;
    const q = this.picture;
    // Frames arrive as copies, so `reached` is compared by content: goals redraw only when progress changes.
    const goalsChanged = !q || p.goals !== q.goals || p.plan !== q.plan || p.goalRadius !== q.goalRadius || p.reached.join() !== q.reached.join();
    this.picture = p;
    if (!q || p.walls !== q.walls) this.cameraDirty = true;
    if (goalsChanged) this.goalsDirty = true;
    this.invalidate();
  }

  private trailFrames: readonly TickFrame[] | null = null;
  private trailCount = 0;

  /** The trail of frames[0 .. count-1]; pass count 0 to hide it. */
  setTrail(frames: readonly TickFrame[], count: number): void {
    if (this.trailFrames === frames && this.trailCount === count) return;
    this.trailFrames = frames;
    this.trailCount = count;
    this.invalidate();
  }

  setTrailVisible(visible: boolean): void {
    this.showTrail = visible;
    this.trail.finished.visible = visible;
    this.trail.live.visible = visible;
    this.backdropDirty = true;
    this.invalidate();
  }

  setEditMarks(m: EditMarks | null): void {
    this.editMarks = m ?? NO_MARKS;
    this.invalidate();
  }

  /** Fits the camera to the bounds (the world's, or its contents'). */
  fit(b: Bounds): void {
    this.camera.fit(b);
    this.cameraDirty = true;
    this.invalidate();
  }

  zoomAt(sx: number, sy: number, factor: number): void {
    this.camera.zoomAt(sx, sy, factor);
    this.cameraDirty = true;
    this.invalidate();
  }

  panBy(dx: number, dy: number): void {
    this.camera.panBy(dx, dy);
    this.cameraDirty = true;
    this.invalidate();
  }

  /** The robot's drawing size in world units: true to scale, but never smaller than a few pixels. */
  robotSize(): number {
    return Math.max(1.6, 11 / this.camera.scale);
  }

  /** Draws at once (outside the animation frame), for measuring. */
  renderNow(): void {
    this.frame(performance.now());
  }

  private resized(): void {
    this.camera.width = Math.max(1, this.host.clientWidth);
    this.camera.height = Math.max(1, this.host.clientHeight);
    this.app.renderer.resize(this.camera.width, this.camera.height);
    this.backdropTexture?.resize(this.camera.width, this.camera.height, this.app.renderer.resolution);
    this.cameraDirty = true;
    this.invalidate();
  }

  private frame(t: number): void {
    this.frameCount++;
    if (t - this.fpsSince >= 1000) {
      this.fps = (this.frameCount * 1000) / (t - this.fpsSince);
      this.frameCount = 0;
      this.fpsSince = t;
    }
    this.beforeFrame?.();
    if (!this.dirty) return;
    this.dirty = false;
    const c = this.camera;
    for (const layer of [this.scene, this.backdropScene]) {
      layer.position.set(c.width / 2 - c.cx * c.scale, c.height / 2 + c.cy * c.scale);
      layer.scale.set(c.scale, -c.scale);
    }
    if (this.cameraDirty) {
      this.cameraDirty = false;
      this.drawGrid();
      this.drawWalls();
      this.backdropDirty = true;
      this.goalsDirty = true;
    }
    if (this.goalsDirty) {
      this.goalsDirty = false;
      this.drawGoals();
    }
    if (this.showTrail && this.trailFrames) this.trail.update(this.trailFrames, Math.min(this.trailCount, this.trailFrames.length), this.robotSize());
    if (this.backdropDirty || this.trail.finishedChanged || this.overlayVersion !== this.overlay.version) {
      this.backdropDirty = false;
      this.trail.finishedChanged = false;
      this.trail.newlyFinished.length = 0;
      this.overlayVersion = this.overlay.version;
      this.app.renderer.render({ container: this.backdrop, target: this.backdropTexture, clear: true, clearColor: this.palette.background });
    } else if (this.trail.newlyFinished.length) {
      // A chunk of the trail filled up: draw just it onto the backdrop, in the camera's frame.
      const m = new Matrix().scale(c.scale, -c.scale).translate(this.backdropScene.position.x, this.backdropScene.position.y);
      for (const chunk of this.trail.newlyFinished) this.app.renderer.render({ container: chunk, target: this.backdropTexture, clear: false, transform: m });
      this.trail.newlyFinished.length = 0;
    }
    this.drawRobot();
    this.drawMarks();
    this.app.render();
  }

  /** A light grid every 1, 2 or 5 x 10^k units, so lines stay 30-90 px apart at any zoom. */
  private drawGrid(): void {
    const g = this.grid.clear();
    const c = this.camera;
    const raw = 48 / c.scale;
    const pow = Math.pow(10, Math.floor(Math.log10(raw)));
    const step = [1, 2, 5, 10].map((m) => m * pow).find((s) => s >= raw) ?? 10 * pow;
    const tl = c.toWorld(0, 0);
    const br = c.toWorld(c.width, c.height);
    for (let x = Math.ceil(tl.x / step) * step; x <= br.x; x += step) {
      const sx = Math.round(c.toScreen(x, 0).x) + 0.5;
      g.moveTo(sx, 0).lineTo(sx, c.height);
    }
    for (let y = Math.ceil(br.y / step) * step; y <= tl.y; y += step) {
      const sy = Math.round(c.toScreen(0, y).y) + 0.5;
      g.moveTo(0, sy).lineTo(c.width, sy);
    }
    g.stroke({ color: this.palette.gridLine, width: 1 });
    const o = c.toScreen(0, 0);
    g.moveTo(Math.round(o.x) + 0.5, 0).lineTo(Math.round(o.x) + 0.5, c.height);
    g.moveTo(0, Math.round(o.y) + 0.5).lineTo(c.width, Math.round(o.y) + 0.5);
    g.stroke({ color: this.palette.axis, width: 1 });
  }

  private px(n: number): number {
    return n / this.camera.scale;
  }

  private drawWalls(): void {
    const g = this.walls.clear();
    const p = this.picture;
    if (!p) return;
    for (const [[x0, y0], [x1, y1]] of p.walls) g.moveTo(x0, y0).lineTo(x1, y1);
    g.stroke({ color: this.palette.wall, width: this.px(4), cap: 'round' });
  }

  private drawGoals(): void {
    const g = this.goals.clear();
    const p = this.picture;
    const seen = new Set<string>();
    if (p) {
      const next = nextGoalName(p);
      const done = new Set(p.plan.filter((_n, i) => p.reached[i] !== null && p.reached[i] !== undefined));
      for (const goal of p.goals) {
        const isNext = goal.name === next;
        const r = Math.max(p.goalRadius, this.px(7));
        const color = isNext ? this.palette.goalNext : done.has(goal.name) && !p.plan.slice(p.reached.indexOf(null)).includes(goal.name) ? this.palette.goalReached : this.palette.goal;
        g.circle(goal.x, goal.y, r).fill({ color, alpha: isNext ? 0.28 : 0.16 }).stroke({ color, width: this.px(isNext ? 3 : 2) });
        g.circle(goal.x, goal.y, this.px(2.5)).fill({ color });
        if (isNext) g.circle(goal.x, goal.y, r + this.px(6)).stroke({ color, width: this.px(1.5), alpha: 0.6 });
        this.label(goal.name, goal.x, goal.y + r, isNext);
        seen.add(goal.name);
      }
    }
    for (const [name, t] of this.labelTexts) {
      if (!seen.has(name)) {
        t.destroy();
        this.labelTexts.delete(name);
      }
    }
  }

  private label(name: string, x: number, y: number, strong: boolean): void {
    let t = this.labelTexts.get(name);
    if (!t) {
      t = new Text({ text: name, style: { fontFamily: 'Inter, "Segoe UI", system-ui, sans-serif', fontSize: 12, fontWeight: '600', fill: this.palette.label } });
      t.anchor.set(0.5, 1);
      this.labels.addChild(t);
      this.labelTexts.set(name, t);
    }
    t.style.fill = strong ? this.palette.goalNext : this.palette.label;
    t.style.fontWeight = strong ? '700' : '600';
    const s = this.camera.toScreen(x, y);
    t.position.set(Math.round(s.x), Math.round(s.y - 4));
  }

  private drawRobot(): void {
    const g = this.robot.clear();
    const p = this.picture;
    if (!p) return;
    const { x, y, heading } = p.robot;
    const w = whiskerSegment(p.robot, p.body);
    g.moveTo(w[0][0], w[0][1]).lineTo(w[1][0], w[1][1]).stroke({ color: p.whisker ? this.palette.whiskerOn : this.palette.whisker, width: this.px(p.whisker ? 3 : 2), cap: 'round' });
    if (p.whisker) g.circle(w[1][0], w[1][1], this.px(3.5)).fill({ color: this.palette.whiskerOn });
    const s = this.robotSize();
    const a = (heading * Math.PI) / 180;
    const pt = (f: number, side: number): number[] => [x + Math.cos(a) * f * s - Math.sin(a) * side * s, y + Math.sin(a) * f * s + Math.cos(a) * side * s];
    g.poly([...pt(1.1, 0), ...pt(-0.7, 0.65), ...pt(-0.4, 0), ...pt(-0.7, -0.65)])
      .fill({ color: p.crash ? this.palette.crash : this.palette.robot })
      .stroke({ color: this.palette.robotEdge, width: this.px(1.5), join: 'round' });
  }

  private drawMarks(): void {
    const g = this.marks.clear();
    const m = this.editMarks;
    const p = this.picture;
    if (!p) return;
    const sel = this.palette.select;
    if (m.selectedWall !== null && p.walls[m.selectedWall]) {
      const [[x0, y0], [x1, y1]] = p.walls[m.selectedWall];
      g.moveTo(x0, y0).lineTo(x1, y1).stroke({ color: sel, width: this.px(8), alpha: 0.35, cap: 'round' });
    }
    if (m.selectedGoal !== null) {
      const goal = p.goals.find((q) => q.name === m.selectedGoal);
      if (goal) g.circle(goal.x, goal.y, Math.max(p.goalRadius, this.px(7)) + this.px(5)).stroke({ color: sel, width: this.px(2.5) });
    }
    if (m.robotSelected) g.circle(p.robot.x, p.robot.y, this.robotSize() * 1.5).stroke({ color: sel, width: this.px(2.5) });
    for (const [hx, hy] of m.handles) g.circle(hx, hy, this.px(5)).fill({ color: 0xffffff }).stroke({ color: sel, width: this.px(2) });
    if (m.preview) {
      const [x0, y0, x1, y1] = m.preview;
      g.moveTo(x0, y0).lineTo(x1, y1).stroke({ color: this.palette.preview, width: this.px(3), cap: 'round', alpha: 0.9 });
    }
  }
}
