/** The world view's colours, read from the page's CSS custom properties so themes apply to it. */
export interface Palette {
  readonly background: number;
  readonly gridLine: number;
  readonly axis: number;
  readonly wall: number;
  readonly goal: number;
  readonly goalNext: number;
  readonly goalReached: number;
  readonly label: number;
  readonly labelBg: number;
  readonly robot: number;
  readonly robotEdge: number;
  readonly whisker: number;
  readonly whiskerOn: number;
  readonly trail: number;
  readonly trailTouch: number;
  readonly crash: number;
  readonly select: number;
  readonly preview: number;
}

const NAMES: Record<keyof Palette, string> = {
  background: '--world-bg',
  gridLine: '--world-grid',
  axis: '--world-axis',
  wall: '--world-wall',
  goal: '--world-goal',
  goalNext: '--world-goal-next',
  goalReached: '--world-goal-reached',
  label: '--world-label',
  labelBg: '--world-label-bg',
  robot: '--world-robot',
  robotEdge: '--world-robot-edge',
  whisker: '--world-whisker',
  whiskerOn: '--world-whisker-on',
  trail: '--world-trail',
  trailTouch: '--world-trail-touch',
  crash: '--world-crash',
  select: '--world-select',
  preview: '--world-preview',
};

function parseColor(text: string): number {
  const t = text.trim();
  const hex = /^#([0-9a-f]{6})$/i.exec(t);
  if (hex) return parseInt(hex[1], 16);
  const short = /^#([0-9a-f])([0-9a-f])([0-9a-f])$/i.exec(t);
  if (short) return parseInt(short[1] + short[1] + short[2] + short[2] + short[3] + short[3], 16);
  return 0xff00ff; // A loud colour makes a missing variable obvious.
}

export function readPalette(el: Element): Palette {
  const css = getComputedStyle(el);
  const out = {} as Record<keyof Palette, number>;
  for (const key of Object.keys(NAMES) as (keyof Palette)[]) out[key] = parseColor(css.getPropertyValue(NAMES[key]));
  return out;
}
