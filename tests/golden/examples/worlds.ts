/** The textbook worlds of DESIGN.md section 6, for testing the example controllers without files. */
import type { WorldSpec } from '../../../app/core/world/world';
type S = [[number, number], [number, number]];
export const office: WorldSpec = {
  name: 'office', walls: [[[20, 0], [30, 20]], [[70, -5], [70, 25]]] as S[],
  goals: [{ name: 'mail', x: -5, y: 10 }, { name: 'o103', x: 50, y: 10 }, { name: 'o109', x: 100, y: 10 }, { name: 'storage', x: 101, y: 51 }],
  plan: ['o109', 'storage', 'o109', 'o103'], robot: { x: 0, y: 0, heading: 90 },
} as unknown as WorldSpec;
export const trap: WorldSpec = {
  name: 'trap', walls: [[[10, -21], [10, 0]], [[10, 10], [10, 31]], [[30, -10], [30, 0]], [[30, 10], [30, 20]], [[50, -21], [50, 31]], [[10, -21], [50, -21]], [[10, 0], [30, 0]], [[10, 10], [30, 10]], [[10, 31], [50, 31]]] as S[],
  goals: [{ name: 'goal', x: 71, y: 0 }], plan: ['goal'], robot: { x: -1, y: 0, heading: 90 },
} as unknown as WorldSpec;
export const trapNew: WorldSpec = {
  name: 'trap-new', walls: [[[10, 51], [60, 51]], [[30, 10], [30, 20]], [[10, -1], [10, 20]], [[10, 30], [10, 51]], [[30, 30], [30, 40]], [[10, -1], [60, -1]], [[10, 30], [30, 30]], [[10, 20], [30, 20]], [[60, -1], [60, 51]]] as S[],
  goals: [{ name: 'goal', x: 90, y: 25 }], plan: ['goal'], robot: { x: 0, y: 25, heading: 90 },
} as unknown as WorldSpec;
