/**
 * Pointer input on the world view: wheel zooms, dragging empty space pans, and the Create tools
 * act (select and drag, draw a wall, place a goal, place and turn the robot, delete). In Solve
 * mode, dragging the robot, a goal or a wall end is an edit sent to the running session.
 * A drag shows a draft while it moves and commits one edit when it ends.
 */
import type { WorldEdit } from '../../core/world/edits';
import type { Segment } from '../../core/world/geometry';
import type { Mode } from '../app/store';
import type { WorldPicture } from '../world-view/picture';
import type { WorldView } from '../world-view/view';
import type { Hit } from './hit';
import { hitTest } from './hit';
import type { CreateState } from './selection';

export interface PointerHost {
  readonly view: WorldView;
  readonly create: CreateState;
  mode(): Mode;
  /** The picture on view (the spec in Create mode, the selected tick in Solve mode). */
  picture(): WorldPicture | null;
  /** Shows an edit in progress (or none). */
  setDraft(edit: WorldEdit | null): void;
  /** Makes an edit: in Create mode to the world spec (undoable), in Solve mode to the session. */
  commit(edit: WorldEdit): void;
  /** Places a new goal at (x, y) with a fresh name. */
  placeGoal(x: number, y: number): void;
  /** Removes what was hit (Create mode). */
  remove(hit: Hit): void;
}

type Drag =
  | { kind: 'pan'; lastX: number; lastY: number }
  | { kind: 'move'; hit: Hit; startX: number; startY: number; edit: WorldEdit | null }
  | { kind: 'wall'; x0: number; y0: number; edit: WorldEdit | null }
  | { kind: 'robot'; x: number; y: number; edit: WorldEdit | null };

const TOLERANCE_PX = 9;

export class PointerInput {
  private drag: Drag | null = null;

  constructor(private readonly host: PointerHost) {
    const canvas = host.view.app.canvas;
    canvas.addEventListener('wheel', (e) => this.wheel(e), { passive: false });
    canvas.addEventListener('pointerdown', (e) => this.down(e));
    canvas.addEventListener('pointermove', (e) => this.move(e));
    canvas.addEventListener('pointerup', (e) => this.up(e));
    canvas.addEventListener('pointercancel', () => this.cancel());
    canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  }

  private local(e: PointerEvent | WheelEvent): { sx: number; sy: number; x: number; y: number } {
    const r = this.host.view.app.canvas.getBoundingClientRect();
    const sx = e.clientX - r.left;
    const sy = e.clientY - r.top;
    const w = this.host.view.camera.toWorld(sx, sy);
    return { sx, sy, x: w.x, y: w.y };
  }

  private wheel(e: WheelEvent): void {
    e.preventDefault();
    const { sx, sy } = this.local(e);
    // Trackpads send many small deltas, mice a few large ones: scale by the delta.
    this.host.view.zoomAt(sx, sy, Math.exp(-Math.max(-200, Math.min(200, e.deltaY)) * 0.0022));
  }

  private down(e: PointerEvent): void {
    const p = this.host.picture();
    if (!p) return;
    const { sx, sy, x, y } = this.local(e);
    this.host.view.app.canvas.setPointerCapture(e.pointerId);
    if (e.button === 1 || e.button === 2) {
      this.drag = { kind: 'pan', lastX: sx, lastY: sy };
      return;
    }
    const c = this.host.create;
    const tol = TOLERANCE_PX / this.host.view.camera.scale;
    const hit = hitTest(p, x, y, tol, this.host.view.robotSize());
    const creating = this.host.mode() === 'create';
    const tool = creating ? c.tool : 'select';
    if (tool === 'wall') {
      this.drag = { kind: 'wall', x0: c.snapValue(x), y0: c.snapValue(y), edit: null };
    } else if (tool === 'goal') {
      if (hit.kind === 'goal') c.select({ kind: 'goal', name: hit.name });
      else this.host.placeGoal(c.snapValue(x), c.snapValue(y));
    } else if (tool === 'robot') {
      this.drag = { kind: 'robot', x: c.snapValue(x), y: c.snapValue(y), edit: null };
      this.host.setDraft({ type: 'moveRobot', x: c.snapValue(x), y: c.snapValue(y) });
      c.select({ kind: 'robot' });
    } else if (tool === 'delete') {
      if (hit.kind !== 'none') this.host.remove(hit);
    } else if (hit.kind === 'none') {
      if (creating) c.select(null);
      this.drag = { kind: 'pan', lastX: sx, lastY: sy };
    } else {
      if (creating) c.select(hit.kind === 'robot' ? { kind: 'robot' } : hit.kind === 'goal' ? { kind: 'goal', name: hit.name } : { kind: 'wall', index: hit.index });
      this.drag = { kind: 'move', hit, startX: x, startY: y, edit: null };
    }
  }

  private move(e: PointerEvent): void {
    const d = this.drag;
    const p = this.host.picture();
    if (!d || !p) {
      this.hover(e);
      return;
    }
    const { sx, sy, x, y } = this.local(e);
    const c = this.host.create;
    if (d.kind === 'pan') {
      this.host.view.panBy(sx - d.lastX, sy - d.lastY);
      d.lastX = sx;
      d.lastY = sy;
      return;
    }
    if (d.kind === 'wall') {
      const wall: Segment = [[d.x0, d.y0], [c.snapValue(x), c.snapValue(y)]];
      d.edit = wall[0][0] === wall[1][0] && wall[0][1] === wall[1][1] ? null : { type: 'addWall', wall };
    } else if (d.kind === 'robot') {
      const heading = Math.round((Math.atan2(y - d.y, x - d.x) * 180) / Math.PI / (c.snap ? 15 : 1)) * (c.snap ? 15 : 1);
      d.edit = Math.hypot(x - d.x, y - d.y) * this.host.view.camera.scale < 6 ? null : { type: 'moveRobot', x: d.x, y: d.y, heading: (heading + 360) % 360 };
    } else {
      d.edit = this.moveEdit(p, d.hit, x - d.startX, y - d.startY, x, y);
    }
    this.host.setDraft(d.edit ?? (d.kind === 'robot' ? { type: 'moveRobot', x: d.x, y: d.y } : null));
  }

  /** The edit that moves what was grabbed: the robot or a goal to the pointer, a wall end, or a whole wall. */
  private moveEdit(p: WorldPicture, hit: Hit, dx: number, dy: number, x: number, y: number): WorldEdit | null {
    const s = (v: number): number => this.host.create.snapValue(v);
    switch (hit.kind) {
      case 'robot':
        return { type: 'moveRobot', x: s(x), y: s(y) };
      case 'goal': {
        const g = p.goals.find((q) => q.name === hit.name);
        return g ? { type: 'setGoal', name: g.name, goal: { name: g.name, x: s(x), y: s(y) } } : null;
      }
      case 'wallEnd': {
        const w = p.walls[hit.index];
        if (!w) return null;
        const moved: [number, number] = [s(x), s(y)];
        return { type: 'setWall', index: hit.index, wall: hit.end === 0 ? [moved, w[1]] : [w[0], moved] };
      }
      case 'wall': {
        const w = p.walls[hit.index];
        if (!w) return null;
        const ddx = s(dx);
        const ddy = s(dy);
        return { type: 'setWall', index: hit.index, wall: [[w[0][0] + ddx, w[0][1] + ddy], [w[1][0] + ddx, w[1][1] + ddy]] };
      }
      case 'none':
        return null;
    }
  }

  private up(e: PointerEvent): void {
    const d = this.drag;
    this.drag = null;
    if (this.host.view.app.canvas.hasPointerCapture(e.pointerId)) this.host.view.app.canvas.releasePointerCapture(e.pointerId);
    if (!d || d.kind === 'pan') return;
    this.host.setDraft(null);
    if (d.kind === 'robot' && !d.edit) this.host.commit({ type: 'moveRobot', x: d.x, y: d.y });
    else if (d.edit) this.host.commit(d.edit);
    if (d.kind === 'wall' && d.edit) {
      const p = this.host.picture();
      if (p) this.host.create.select({ kind: 'wall', index: p.walls.length - 1 });
    }
  }

  private cancel(): void {
    this.drag = null;
    this.host.setDraft(null);
  }

  /** Shows what a click would grab. */
  private hover(e: PointerEvent): void {
    const p = this.host.picture();
    if (!p) return;
    const { x, y } = this.local(e);
    const tool = this.host.mode() === 'create' ? this.host.create.tool : 'select';
    let cursor = 'grab';
    if (tool === 'wall' || tool === 'goal' || tool === 'robot') cursor = 'crosshair';
    else {
      const hit = hitTest(p, x, y, TOLERANCE_PX / this.host.view.camera.scale, this.host.view.robotSize());
      if (hit.kind !== 'none') cursor = tool === 'delete' ? 'not-allowed' : 'move';
      else if (tool === 'delete') cursor = 'default';
    }
    this.host.view.app.canvas.style.cursor = cursor;
  }
}
