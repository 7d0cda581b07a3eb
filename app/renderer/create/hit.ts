/** What lies under the pointer in the world: pure geometry over a picture, in world units. */
import type { WorldPicture } from '../world-view/picture';

export type Hit =
  | { readonly kind: 'robot' }
  | { readonly kind: 'goal'; readonly name: string }
  | { readonly kind: 'wallEnd'; readonly index: number; readonly end: 0 | 1 }
  | { readonly kind: 'wall'; readonly index: number }
  | { readonly kind: 'none' };

function distToSegment(px: number, py: number, x0: number, y0: number, x1: number, y1: number): number {
  const dx = x1 - x0;
  const dy = y1 - y0;
  const len2 = dx * dx + dy * dy;
  const t = len2 === 0 ? 0 : Math.max(0, Math.min(1, ((px - x0) * dx + (py - y0) * dy) / len2));
  return Math.hypot(px - (x0 + t * dx), py - (y0 + t * dy));
}

/**
 * The nearest thing within `tol` world units, preferring the robot, then goals, then wall ends
 * (so a wall's end can be grabbed where it meets another wall), then walls.
 */
export function hitTest(p: WorldPicture, x: number, y: number, tol: number, robotSize: number): Hit {
  if (Math.hypot(x - p.robot.x, y - p.robot.y) <= Math.max(tol, robotSize)) return { kind: 'robot' };
  let best: Hit = { kind: 'none' };
  let bestD = Infinity;
  for (const g of p.goals) {
    const d = Math.hypot(x - g.x, y - g.y);
    if (d <= Math.max(tol, p.goalRadius) && d < bestD) {
      best = { kind: 'goal', name: g.name };
      bestD = d;
    }
  }
  if (best.kind !== 'none') return best;
  for (let i = p.walls.length - 1; i >= 0; i--) {
    const [[x0, y0], [x1, y1]] = p.walls[i];
    const d0 = Math.hypot(x - x0, y - y0);
    const d1 = Math.hypot(x - x1, y - y1);
    if (d0 <= tol && d0 < bestD) {
      best = { kind: 'wallEnd', index: i, end: 0 };
      bestD = d0;
    }
    if (d1 <= tol && d1 < bestD) {
      best = { kind: 'wallEnd', index: i, end: 1 };
      bestD = d1;
    }
  }
  if (best.kind !== 'none') return best;
  for (let i = p.walls.length - 1; i >= 0; i--) {
    const [[x0, y0], [x1, y1]] = p.walls[i];
    const d = distToSegment(x, y, x0, y0, x1, y1);
    if (d <= tol && d < bestD) {
      best = { kind: 'wall', index: i };
      bestD = d;
    }
  }
  return best;
}
