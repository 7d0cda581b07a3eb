/**
 * The controller diagram's layout, DOM-free (unit-tested in Node): layers become horizontal bands,
 * top layer first; functions become ovals in rows inside their band, ordered by the dependencies
 * within the band; arcs become smooth arrows routed through the gaps between ovals (a small
 * layered-graph layout: ranks, barycentre ordering, placement, routing through dummy points).
 * Previous-tick arcs leave through an output port on the right edge of the source's band and come
 * back through the matching input port on its left edge, at the same height, as in the original
 * design. The world inputs in use sit in a row of boxes below the bottom band, next to the body
 * that receives the body command.
 */
import type { ControllerSpec, FunctionSpec, LayerSpec, WorldInputName } from '../../core/controller/model';
import { WORLD_INPUTS } from '../../core/controller/model';

export interface Point {
  readonly x: number;
  readonly y: number;
}

export interface Box {
  /** Centre. */
  readonly x: number;
  readonly y: number;
  readonly w: number;
  readonly h: number;
}

export type NodeKind = 'function' | 'world' | 'random' | 'body' | 'port-in' | 'port-out';

/** Something drawn: an oval, a box, or a port. Coordinates are the centre. */
export interface DiagramNode extends Box {
  /** `fn:name`, `world:robotPos`, `random:name`, `body`, `in:name`, `out:name`. */
  readonly id: string;
  readonly kind: NodeKind;
  readonly label: string;
  /** The band's layer, or null for the world row. */
  readonly layer: string | null;
  /** For functions and ports: the function. */
  readonly function: string | null;
  /** The global row (0 is the top row of the top band; the world row is the last). */
  readonly row: number;
  /** The function whose output drives the body. */
  readonly bodyCommand: boolean;
}

export type ArcKind = 'this' | 'previous-in' | 'previous-out' | 'world' | 'random' | 'body';

export interface DiagramArc {
  readonly id: string;
  readonly kind: ArcKind;
  /** Node ids. */
  readonly from: string;
  readonly to: string;
  /** The input this arc feeds (its name), or null for the arcs into a port and into the body. */
  readonly input: string | null;
  /** The function that reads the arc, or null (into a port or the body). */
  readonly target: string | null;
  /** The source as the engine's arc rows name it: `todo`, `previous.todo`, `world.plan`, `random.coin`. */
  readonly source: string;
  /** The route: the start, the points it passes through, the end (at the target's outline). */
  readonly points: readonly Point[];
  /** The cubic segments between the points. */
  readonly segments: readonly Segment[];
  /** SVG path data through the points. */
  readonly path: string;
  /** Where the chip with the input's name goes (centre and size), or null. */
  readonly label: Box | null;
}

/**
 * Where a source's value is shown: arcs from one source carry one value, so it is shown once, on
 * the trunk the arcs share as they leave the source (a function, a port, a world input, a random source).
 */
export interface ValueChip {
  /** The source as the engine's arc rows name it (`todo`, `previous.todo`, `world.plan`, `random.coin`). */
  readonly source: string;
  /** The node the value leaves. */
  readonly node: string;
  /** The arcs (ids) that carry it. */
  readonly arcs: readonly string[];
  readonly box: Box;
}

export interface DiagramBand {
  readonly layer: string;
  readonly index: number;
  /** Top-left corner and size. */
  readonly x: number;
  readonly y: number;
  readonly w: number;
  readonly h: number;
  /** Baseline of the layer's name. */
  readonly titleY: number;
  /** Layer variables as lines of `NAME = value` text, wrapped to the band. */
  readonly variables: readonly string[];
  readonly firstVariableY: number;
}

export interface DiagramLayout {
  readonly width: number;
  readonly height: number;
  readonly bands: readonly DiagramBand[];
  readonly nodes: readonly DiagramNode[];
  readonly arcs: readonly DiagramArc[];
  /** Where each source's value goes at a tick. */
  readonly values: readonly ValueChip[];
  /** The world row's area (top-left corner and size), or null when nothing reads the world. */
  readonly world: { readonly x: number; readonly y: number; readonly w: number; readonly h: number; readonly titleY: number } | null;
}

/** Sizes, in diagram units (CSS pixels at zoom 1). */
export const SIZES = {
  ovalH: 28,
  boxH: 22,
  portSize: 10,
  rowGap: 46,
  gutter: 22,
  bandPad: 13,
  titleH: 20,
  variableLine: 13,
  nodeGap: 18,
  worldGap: 9,
  dummyGap: 7,
  minWidth: 300,
  maxRowWidth: 380,
  /** Approximate character widths of the fonts the view uses. */
  fnChar: 6.7,
  boxChar: 6,
  smallChar: 5.5,
  /** Value chips have room for this many characters; name chips are one line high. */
  valueChars: 13,
  valueChar: 6,
  chipH: 15,
} as const;

/** The width an oval needs for a function name. */
export function ovalWidth(name: string): number {
  return Math.max(66, Math.round(name.length * SIZES.fnChar + 24));
}

/** The size of the chip with an input's name. */
export function chipSize(input: string): { w: number; h: number } {
  return { w: Math.round(input.length * SIZES.smallChar + 8), h: SIZES.chipH - 1 };
}

/** The size reserved for a value chip. */
export const VALUE_CHIP = { w: SIZES.valueChars * SIZES.valueChar + 8, h: SIZES.chipH } as const;

interface MNode {
  id: string;
  kind: NodeKind | 'dummy';
  label: string;
  layer: string | null;
  fn: string | null;
  band: number; // -1: world row
  rank: number; // within the band
  row: number;
  w: number;
  h: number;
  x: number;
  y: number;
  bodyCommand: boolean;
  /** Order key within the row while ordering. */
  pos: number;
}

interface Edge {
  id: string;
  kind: ArcKind;
  from: MNode;
  to: MNode;
  input: string | null;
  target: string | null;
  source: string;
  /** The bus the edge travels on (shared by every edge from one source in one direction). */
  bus: string;
  via: MNode[];
}

/** Lays the controller out. Unknown arc sources (a controller being edited) are left out. */
export function layoutController(spec: ControllerSpec): DiagramLayout {
  const layers = spec.layers;
  const nodes = new Map<string, MNode>();
  const fnBand = new Map<string, number>();
  const fnSpec = new Map<string, FunctionSpec>();
  layers.forEach((layer, b) =>
    layer.functions.forEach((fn) => {
      if (fnBand.has(fn.name)) return;
      fnBand.set(fn.name, b);
      fnSpec.set(fn.name, fn);
    }),
  );
  const randomBand = new Map<string, number>();
  layers.forEach((layer, b) => layer.randomSources.forEach((r) => randomBand.has(r.name) || randomBand.set(r.name, b)));

  const add = (n: Omit<MNode, 'row' | 'x' | 'y' | 'pos'>): MNode => {
    const m: MNode = { ...n, row: 0, x: 0, y: 0, pos: 0 };
    nodes.set(m.id, m);
    return m;
  };

  // Nodes of the bands: functions and random sources.
  layers.forEach((layer, b) => {
    for (const r of layer.randomSources) {
      if (randomBand.get(r.name) !== b) continue;
      add({ id: `random:${r.name}`, kind: 'random', label: r.name, layer: layer.name, fn: null, band: b, rank: 0, w: boxWidth(r.name) + 14, h: SIZES.boxH - 2, bodyCommand: false });
    }
    for (const fn of layer.functions) {
      if (fnBand.get(fn.name) !== b) continue;
      add({ id: `fn:${fn.name}`, kind: 'function', label: fn.name, layer: layer.name, fn: fn.name, band: b, rank: 0, w: ovalWidth(fn.name), h: SIZES.ovalH, bodyCommand: fn.name === spec.bodyCommand, });
    }
  });

  // Ranks within each band: a function sits below every function (and random source) of its band it reads this tick.
  layers.forEach((layer, b) => rankBand(layer, b, nodes, fnBand, randomBand));

  // Edges, one per input (plus the arcs into output ports and into the body).
  const edges: Edge[] = [];
  const worldUsed = new Set<WorldInputName>();
  const portsOf = new Set<string>();
  for (const [name, fn] of fnSpec) {
    const to = nodes.get(`fn:${name}`)!;
    for (const inp of fn.inputs) {
      const f = inp.from;
      const base = { input: inp.name, target: name, id: `${name}/${inp.name}` };
      if (f.kind === 'function') {
        const from = nodes.get(`fn:${f.function}`);
        if (!from || from === to) continue;
        edges.push({ ...base, kind: 'this', from, to, source: f.function, bus: '', via: [] });
      } else if (f.kind === 'previous') {
        if (!fnBand.has(f.function)) continue;
        portsOf.add(f.function);
        edges.push({ ...base, kind: 'previous-in', from: null as unknown as MNode, to, source: `previous.${f.function}`, bus: f.function, via: [] });
      } else if (f.kind === 'world') {
        if (!(WORLD_INPUTS as readonly string[]).includes(f.input)) continue;
        worldUsed.add(f.input);
        edges.push({ ...base, kind: 'world', from: null as unknown as MNode, to, source: `world.${f.input}`, bus: f.input, via: [] });
      } else if (f.kind === 'random') {
        const from = nodes.get(`random:${f.source}`);
        if (!from) continue;
        edges.push({ ...base, kind: 'random', from, to, source: `random.${f.source}`, bus: '', via: [] });
      }
    }
  }

  // Matching ports: one pair per function read from the previous tick, at its height in its band.
  for (const name of portsOf) {
    const src = nodes.get(`fn:${name}`)!;
    const common = { layer: src.layer, fn: name, band: src.band, rank: src.rank, w: SIZES.portSize, h: SIZES.portSize, bodyCommand: false };
    add({ ...common, id: `in:${name}`, kind: 'port-in', label: name });
    const out = add({ ...common, id: `out:${name}`, kind: 'port-out', label: name });
    edges.push({ id: `${name}/out`, kind: 'previous-out', from: src, to: out, input: null, target: null, source: name, bus: '', via: [] });
  }
  for (const e of edges) if (e.kind === 'previous-in') e.from = nodes.get(`in:${e.bus}`)!;

  // The world row: the world inputs in use, and the body.
  const bodyFn = nodes.get(`fn:${spec.bodyCommand}`);
  const worldRow = worldUsed.size > 0 || bodyFn !== undefined;
  for (const w of WORLD_INPUTS) {
    if (!worldUsed.has(w)) continue;
    add({ id: `world:${w}`, kind: 'world', label: w, layer: null, fn: null, band: -1, rank: 0, w: boxWidth(w), h: SIZES.boxH, bodyCommand: false });
  }
  for (const e of edges) if (e.kind === 'world') e.from = nodes.get(`world:${e.bus}`)!;
  if (bodyFn) {
    const body = add({ id: 'body', kind: 'body', label: 'to the body', layer: null, fn: null, band: -1, rank: 0, w: boxWidth('to the body') + 8, h: SIZES.boxH, bodyCommand: false });
    edges.push({ id: 'body', kind: 'body', from: bodyFn, to: body, input: null, target: null, source: bodyFn.fn!, bus: '', via: [] });
  }

  // Rows: each band's ranks in turn (wrapping rows that would be too wide), then the world row.
  const rows: MNode[][] = [];
  const rowBand: number[] = [];
  const pushRow = (row: MNode[], band: number): void => {
    for (const n of row) n.row = rows.length;
    rows.push(row);
    rowBand.push(band);
  };
  layers.forEach((_layer, b) => {
    const inBand = [...nodes.values()].filter((n) => n.band === b && n.kind !== 'port-in' && n.kind !== 'port-out');
    const maxRank = Math.max(0, ...inBand.map((n) => n.rank));
    for (let r = 0; r <= maxRank; r++) {
      let row: MNode[] = [];
      let width = 0;
      for (const n of inBand.filter((m) => m.rank === r)) {
        if (row.length > 0 && width + n.w > SIZES.maxRowWidth) {
          pushRow(row, b);
          row = [];
          width = 0;
        }
        row.push(n);
        width += n.w + SIZES.nodeGap;
      }
      if (row.length > 0 || r === 0) pushRow(row, b);
    }
  });
  const worldRowIndex = rows.length;
  if (worldRow) pushRow([...nodes.values()].filter((n) => n.band === -1), -1);
  for (const n of nodes.values()) if (n.kind === 'port-in' || n.kind === 'port-out') n.row = nodes.get(`fn:${n.fn}`)!.row;

  // Buses: each source's edges that go up (or down) share their dummy points row by row.
  const dummies = new Map<string, MNode>();
  for (const e of edges) {
    if (e.from.row === e.to.row) continue;
    const dir = e.to.row > e.from.row ? 1 : -1;
    e.bus = `${e.from.id}:${dir > 0 ? 'down' : 'up'}`;
    for (let r = e.from.row + dir; r !== e.to.row; r += dir) {
      const id = `d:${e.bus}:${r}`;
      let d = dummies.get(id);
      if (!d) {
        d = { id, kind: 'dummy', label: '', layer: null, fn: null, band: rowBand[r], rank: 0, row: r, w: 2, h: 0, x: 0, y: 0, bodyCommand: false, pos: 0 };
        dummies.set(id, d);
        rows[r].push(d);
      }
      e.via.push(d);
    }
  }

  // Neighbours along the routes, for ordering and placement.
  const nbrs = new Map<MNode, MNode[]>();
  const link = (a: MNode, b: MNode): void => {
    if (!nbrs.has(a)) nbrs.set(a, []);
    if (!nbrs.has(b)) nbrs.set(b, []);
    nbrs.get(a)!.push(b);
    nbrs.get(b)!.push(a);
  };
  const linked = new Set<string>();
  for (const e of edges) {
    const chain = [e.from, ...e.via, e.to];
    for (let i = 0; i + 1 < chain.length; i++) {
      const key = `${chain[i].id}|${chain[i + 1].id}`;
      if (linked.has(key)) continue;
      linked.add(key);
      link(chain[i], chain[i + 1]);
    }
  }

  orderRows(rows, nbrs);
  const width = placeRows(rows, nbrs);

  // Vertical positions: each band's header, its rows, then the world row.
  const bands: DiagramBand[] = [];
  let y = 0;
  const rowY: number[] = [];
  const rowH = rows.map((row) => Math.max(SIZES.ovalH, ...row.map((n) => n.h)));
  layers.forEach((layer, b) => {
    const top = y;
    const variables = wrapVariables(layer, width - 2 * SIZES.gutter + 24);
    const titleY = top + 16;
    const firstVariableY = titleY + SIZES.variableLine;
    y = titleY + variables.length * SIZES.variableLine + SIZES.bandPad + 8;
    const bandRows = rows.map((_r, i) => i).filter((i) => rowBand[i] === b);
    bandRows.forEach((i, k) => {
      if (k > 0) y += SIZES.rowGap;
      rowY[i] = y + rowH[i] / 2;
      y += rowH[i];
    });
    y += SIZES.bandPad + 4;
    bands.push({ layer: layer.name, index: b, x: 0, y: top, w: width, h: y - top, titleY, variables, firstVariableY });
  });
  let world: DiagramLayout['world'] = null;
  if (worldRow) {
    const top = y;
    y += SIZES.rowGap - 8;
    rowY[worldRowIndex] = y + rowH[worldRowIndex] / 2;
    y += rowH[worldRowIndex] + 20;
    world = { x: 0, y: top, w: width, h: y - top, titleY: y - 7 };
  }
  for (let i = 0; i < rows.length; i++) for (const n of rows[i]) n.y = rowY[i] ?? 0;

  // Ports on the band edges, stacked when several share a row.
  const byRow = new Map<number, MNode[]>();
  for (const n of nodes.values()) {
    if (n.kind !== 'port-in') continue;
    if (!byRow.has(n.row)) byRow.set(n.row, []);
    byRow.get(n.row)!.push(n);
  }
  for (const [row, ins] of byRow) {
    ins.sort((a, b) => nodes.get(`fn:${a.fn}`)!.x - nodes.get(`fn:${b.fn}`)!.x);
    ins.forEach((p, k) => {
      const dy = (k - (ins.length - 1) / 2) * (SIZES.portSize + 6);
      p.x = 0;
      p.y = rowY[row] + dy;
      const out = nodes.get(`out:${p.fn}`)!;
      out.x = width;
      out.y = p.y;
    });
  }

  // Routes: attach each edge to its ends' outlines, spread along the side it leaves or enters by.
  const lift = new Map<Edge, number>();
  for (const e of edges) {
    const port = e.kind === 'previous-out' ? e.to : e.kind === 'previous-in' && e.from.row === e.to.row ? e.from : null;
    if (!port) continue;
    const other = port === e.to ? e.from : e.to;
    const lo = Math.min(port.x, other.x);
    const hi = Math.max(port.x, other.x);
    const blocked = rows[other.row].some((n) => n !== other && n.kind !== 'dummy' && n.x > lo && n.x < hi);
    if (!blocked) continue;
    const r = other.row;
    const lastInBand = rowBand[r + 1] !== rowBand[r];
    const firstInBand = r === 0 || rowBand[r - 1] !== rowBand[r];
    const below = rowY[r] + rowH[r] / 2;
    const above = rowY[r] - rowH[r] / 2;
    lift.set(e, !lastInBand ? below + SIZES.rowGap / 2 : !firstInBand ? above - SIZES.rowGap / 2 : below + SIZES.bandPad / 2);
  }
  const arcs = route(edges, lift);
  const headers: Box[] = bands.map((b) => {
    const textW = Math.max(b.layer.length * 8, ...b.variables.map((v) => v.length * SIZES.smallChar)) + 16;
    const h = b.firstVariableY + (b.variables.length - 1) * SIZES.variableLine + 4 - b.y;
    return { x: b.x + textW / 2, y: b.y + h / 2, w: textW, h };
  });
  if (world) headers.push({ x: 60, y: world.titleY - 4, w: 120, h: 12 });
  const values = placeLabels(arcs, [...nodes.values()], headers, width);

  const outNodes: DiagramNode[] = [...nodes.values()].map((n) => ({
    id: n.id,
    kind: n.kind as NodeKind,
    label: n.label,
    layer: n.layer,
    function: n.fn,
    row: n.row,
    x: n.x,
    y: n.y,
    w: n.w,
    h: n.h,
    bodyCommand: n.bodyCommand,
  }));
  return { width, height: y, bands, nodes: outNodes, arcs, values, world };
}

function boxWidth(text: string): number {
  return Math.round(text.length * SIZES.boxChar + 14);
}

/** Longest-path ranks inside one band; the body command goes to the band's last rank. */
function rankBand(layer: LayerSpec, b: number, nodes: Map<string, MNode>, fnBand: Map<string, number>, randomBand: Map<string, number>): void {
  const own = layer.functions.filter((f) => fnBand.get(f.name) === b);
  const deps = new Map<string, string[]>();
  for (const fn of own) {
    const d: string[] = [];
    for (const inp of fn.inputs) {
      if (inp.from.kind === 'function' && fnBand.get(inp.from.function) === b && inp.from.function !== fn.name) d.push(`fn:${inp.from.function}`);
      if (inp.from.kind === 'random' && randomBand.get(inp.from.source) === b) d.push(`random:${inp.from.source}`);
    }
    deps.set(`fn:${fn.name}`, d);
  }
  // Relax at most n times: a cycle (an error the engine reports) cannot make this loop forever.
  for (let pass = 0; pass <= own.length; pass++) {
    let changed = false;
    for (const [id, d] of deps) {
      const n = nodes.get(id)!;
      const r = Math.max(0, ...d.map((x) => nodes.get(x)!.rank + 1));
      if (r > n.rank && r <= own.length + 1) {
        n.rank = r;
        changed = true;
      }
    }
    if (!changed) break;
  }
  const body = [...deps.keys()].map((id) => nodes.get(id)!).find((n) => n.bodyCommand);
  if (body) {
    const max = Math.max(0, ...[...deps.keys()].map((id) => nodes.get(id)!.rank));
    const feedsOthers = [...deps.values()].some((d) => d.includes(body.id));
    if (!feedsOthers) body.rank = max;
  }
}

/** Orders each row by the barycentre of its neighbours (a few sweeps); ports pull to their edges. */
function orderRows(rows: MNode[][], nbrs: Map<MNode, MNode[]>): void {
  const rel = (n: MNode): number => {
    if (n.kind === 'port-in') return -0.6;
    if (n.kind === 'port-out') return 1.6;
    return n.pos;
  };
  const setPos = (row: MNode[]): void => row.forEach((n, i) => (n.pos = (i + 0.5) / row.length));
  rows.forEach(setPos);
  for (let sweep = 0; sweep < 12; sweep++) {
    const down = sweep % 2 === 0;
    const order = rows.map((_r, i) => i);
    if (!down) order.reverse();
    for (const i of order) {
      const row = rows[i];
      const keyed = row.map((n, k) => {
        const ns = nbrs.get(n) ?? [];
        const adjacent = ns.filter((m) => (down ? m.row < n.row : m.row > n.row) || m.row === n.row);
        const use = adjacent.length ? adjacent : ns;
        const bary = use.length ? use.reduce((s, m) => s + rel(m), 0) / use.length : n.pos;
        return { n, key: bary, k };
      });
      keyed.sort((a, b) => a.key - b.key || a.k - b.k);
      rows[i] = keyed.map((e) => e.n);
      setPos(rows[i]);
    }
  }
}

/** Horizontal positions: each node near its neighbours' average, keeping the order and the gaps. */
function placeRows(rows: MNode[][], nbrs: Map<MNode, MNode[]>): number {
  const gap = (a: MNode, b: MNode): number =>
    (a.w + b.w) / 2 + (a.kind === 'dummy' || b.kind === 'dummy' ? SIZES.dummyGap : a.band === -1 && b.band === -1 ? SIZES.worldGap : SIZES.nodeGap);
  const widthOf = (row: MNode[]): number => row.reduce((s, n, i) => s + n.w + (i > 0 ? gap(row[i - 1], n) - (row[i - 1].w + n.w) / 2 : 0), 0);
  const maxW = Math.max(SIZES.minWidth - 2 * SIZES.gutter, ...rows.map(widthOf));
  for (const row of rows) {
    let x = (maxW - widthOf(row)) / 2;
    row.forEach((n, i) => {
      if (i > 0) x += gap(row[i - 1], n) - (row[i - 1].w + n.w) / 2;
      n.x = x + n.w / 2;
      x += n.w;
    });
  }
  let left = 0;
  let right = maxW;
  const at = (m: MNode): number => (m.kind === 'port-in' ? left - SIZES.gutter : m.kind === 'port-out' ? right + SIZES.gutter : m.x);
  for (let it = 0; it < 24; it++) {
    const order = rows.map((_r, i) => i);
    if (it % 2) order.reverse();
    for (const i of order) {
      const row = rows[i];
      if (row.length === 0) continue;
      const want = row.map((n) => {
        const ns = nbrs.get(n) ?? [];
        if (ns.length === 0) return n.x;
        // Dummies follow their chain closely; ovals also keep some of their place.
        const avg = ns.reduce((s, m) => s + at(m), 0) / ns.length;
        return n.kind === 'dummy' ? avg : 0.35 * n.x + 0.65 * avg;
      });
      const a = want.slice();
      for (let k = 1; k < row.length; k++) a[k] = Math.max(a[k], a[k - 1] + gap(row[k - 1], row[k]));
      const c = want.slice();
      for (let k = row.length - 2; k >= 0; k--) c[k] = Math.min(c[k], c[k + 1] - gap(row[k], row[k + 1]));
      row.forEach((n, k) => (n.x = (a[k] + c[k]) / 2));
    }
    left = Math.min(...rows.flatMap((r) => r.map((n) => n.x - n.w / 2)));
    right = Math.max(...rows.flatMap((r) => r.map((n) => n.x + n.w / 2)));
    // Keep the drawing from drifting apart: pull wide spreads back to the widest row's width.
    if (right - left > maxW * 1.08) {
      const mid = (left + right) / 2;
      const k = (maxW * 1.08) / (right - left);
      for (const row of rows) for (const n of row) n.x = mid + (n.x - mid) * k;
      for (const row of rows) for (let q = 1; q < row.length; q++) row[q].x = Math.max(row[q].x, row[q - 1].x + gap(row[q - 1], row[q]));
    }
  }
  left = Math.min(...rows.flatMap((r) => r.map((n) => n.x - n.w / 2)));
  right = Math.max(...rows.flatMap((r) => r.map((n) => n.x + n.w / 2)));
  const shift = SIZES.gutter - left;
  for (const row of rows) for (const n of row) n.x += shift;
  return Math.max(SIZES.minWidth, right - left + 2 * SIZES.gutter);
}

function wrapVariables(layer: LayerSpec, width: number): string[] {
  const parts = layer.variables.map((v) => `${v.name} = ${shortJson(v.value)}`);
  const lines: string[] = [];
  let line = '';
  for (const p of parts) {
    const next = line ? `${line}  ·  ${p}` : p;
    if (line && next.length * SIZES.smallChar > width) {
      lines.push(line);
      line = p;
    } else line = next;
  }
  if (line) lines.push(line);
  return lines;
}

function shortJson(v: unknown): string {
  let s: string;
  try {
    s = JSON.stringify(v) ?? String(v);
  } catch {
    s = String(v);
  }
  return s.length > 24 ? `${s.slice(0, 23)}…` : s;
}

type Side = 'top' | 'bottom' | 'left' | 'right';

/** Turns edges into routes: ends on the outlines, spread along each side, smooth curves between. */
function route(edges: Edge[], lift: Map<Edge, number>): DiagramArc[] {
  // Which side each end uses, and the x (or y) of the point it heads to, for spreading.
  interface End { node: MNode; side: Side; key: string; toward: number }
  const ends = new Map<MNode, End[]>();
  const addEnd = (e: End): End => {
    if (!ends.has(e.node)) ends.set(e.node, []);
    const list = ends.get(e.node)!;
    const same = list.find((x) => x.key === e.key);
    if (same) return same;
    list.push(e);
    return e;
  };
  const sideTo = (n: MNode, other: MNode): Side => (other.row < n.row ? 'top' : other.row > n.row ? 'bottom' : other.x < n.x ? 'left' : 'right');
  const plan = edges.map((e) => {
    const chain = [e.from, ...e.via, e.to];
    const next = chain[1];
    const prev = chain[chain.length - 2];
    const ly = lift.get(e);
    let startSide: Side = e.from.kind === 'port-in' || e.to.kind === 'port-out' ? 'right' : sideTo(e.from, next);
    let endSide: Side = e.to.kind === 'port-out' || (e.from.kind === 'port-in' && e.from.row === e.to.row) ? 'left' : sideTo(e.to, prev);
    if (ly !== undefined) {
      // Around the ovals in the way: down (or up) to the channel, along it, and back.
      const side: Side = ly > e.from.y ? 'bottom' : 'top';
      if (e.kind === 'previous-out') startSide = side;
      else endSide = side;
    }
    // Edges of one bus leave by one point; each edge enters by its own.
    const start = addEnd({ node: e.from, side: startSide, key: `out:${e.bus || e.id}`, toward: startSide === 'left' || startSide === 'right' ? next.y : next.x });
    const end = addEnd({ node: e.to, side: endSide, key: `in:${e.id}`, toward: endSide === 'left' || endSide === 'right' ? prev.y : prev.x });
    return { e, chain, start, end, ly };
  });
  const where = new Map<End, Point>();
  for (const [node, list] of ends) {
    for (const side of ['top', 'bottom', 'left', 'right'] as Side[]) {
      const group = list.filter((x) => x.side === side).sort((a, b) => a.toward - b.toward);
      group.forEach((end, k) => where.set(end, anchor(node, side, group.length === 1 ? 0 : k / (group.length - 1) - 0.5, group.length)));
    }
  }
  const tangent = (side: Side): 'h' | 'v' => (side === 'left' || side === 'right' ? 'h' : 'v');
  return plan.map(({ e, chain, start, end, ly }) => {
    const pts: TPoint[] = [{ ...where.get(start)!, t: tangent(start.side) }];
    for (const d of chain.slice(1, -1)) pts.push({ x: d.x, y: d.y, t: 'v' });
    if (ly !== undefined) {
      // The port end of the route sits at the band edge; the channel point just inside it.
      const port = e.kind === 'previous-out' ? e.to : e.from;
      const other = e.kind === 'previous-out' ? e.from : e.to;
      const x = port.x + (port.kind === 'port-out' ? -16 : 16);
      const mid = { x: (x + other.x) / 2, y: ly, t: 'h' as const };
      if (e.kind === 'previous-out') pts.push(mid, { x, y: ly, t: 'h' });
      else pts.push({ x, y: ly, t: 'h' }, mid);
    }
    pts.push({ ...where.get(end)!, t: tangent(end.side) });
    const segments = segmentsThrough(pts);
    return {
      id: e.id,
      kind: e.kind,
      from: e.from.id,
      to: e.to.id,
      input: e.input,
      target: e.target,
      source: e.source,
      points: pts.map(({ x, y }) => ({ x, y })),
      segments,
      path: pathOf(segments),
      label: null,
    };
  });
}

interface TPoint extends Point {
  /** The direction the route passes the point in: horizontal or vertical. */
  readonly t: 'h' | 'v';
}

/** A point on a node's outline: `t` in [-0.5, 0.5] along the side. */
function anchor(n: MNode, side: Side, t: number, count: number): Point {
  if (n.kind === 'port-in' || n.kind === 'port-out') {
    const h = n.w / 2;
    return side === 'left' ? { x: n.x - h, y: n.y } : side === 'right' ? { x: n.x + h, y: n.y } : { x: n.x, y: n.y + (side === 'top' ? -h : h) };
  }
  if (n.kind === 'function') {
    const rx = n.w / 2;
    const ry = n.h / 2;
    if (side === 'left' || side === 'right') {
      const dy = t * ry * 0.9;
      const dx = rx * Math.sqrt(Math.max(0, 1 - (dy / ry) ** 2));
      return { x: n.x + (side === 'left' ? -dx : dx), y: n.y + dy };
    }
    const spread = Math.min(0.8, 0.25 + 0.12 * count);
    const dx = t * 2 * rx * spread;
    const dy = ry * Math.sqrt(Math.max(0, 1 - (dx / rx) ** 2));
    return { x: n.x + dx, y: n.y + (side === 'top' ? -dy : dy) };
  }
  const w = n.w / 2;
  const h = n.h / 2;
  if (side === 'left' || side === 'right') return { x: n.x + (side === 'left' ? -w : w), y: n.y + t * h };
  return { x: n.x + t * 2 * w * 0.8, y: n.y + (side === 'top' ? -h : h) };
}

/** One cubic segment of a route. */
export interface Segment {
  readonly p: Point;
  readonly c1: Point;
  readonly c2: Point;
  readonly q: Point;
}

/** Smooth cubic segments, passing each point horizontally or vertically as it asks. */
function segmentsThrough(points: readonly TPoint[]): Segment[] {
  const out: Segment[] = [];
  for (let i = 0; i + 1 < points.length; i++) {
    const p = points[i];
    const q = points[i + 1];
    const dx = q.x - p.x;
    const dy = q.y - p.y;
    const hx = Math.sign(dx || 1) * Math.max(Math.abs(dx) / 2, Math.min(24, Math.abs(dy)));
    const c1 = p.t === 'h' ? { x: p.x + hx, y: p.y } : { x: p.x, y: p.y + dy / 2 };
    const c2 = q.t === 'h' ? { x: q.x - hx, y: q.y } : { x: q.x, y: q.y - dy / 2 };
    out.push({ p: { x: p.x, y: p.y }, c1, c2, q: { x: q.x, y: q.y } });
  }
  return out;
}

function pathOf(segments: readonly Segment[]): string {
  const r = (v: number): number => Math.round(v * 10) / 10;
  let d = `M${r(segments[0].p.x)},${r(segments[0].p.y)}`;
  for (const { c1, c2, q } of segments) d += ` C${r(c1.x)},${r(c1.y)} ${r(c2.x)},${r(c2.y)} ${r(q.x)},${r(q.y)}`;
  return d;
}

/** The point at `t` on a cubic segment. */
export function pointOn(s: Segment, t: number): Point {
  const u = 1 - t;
  return {
    x: u * u * u * s.p.x + 3 * u * u * t * s.c1.x + 3 * u * t * t * s.c2.x + t * t * t * s.q.x,
    y: u * u * u * s.p.y + 3 * u * u * t * s.c1.y + 3 * u * t * t * s.c2.y + t * t * t * s.q.y,
  };
}

function overlap(a: Box, b: Box): number {
  const w = Math.min(a.x + a.w / 2, b.x + b.w / 2) - Math.max(a.x - a.w / 2, b.x - b.w / 2);
  const h = Math.min(a.y + a.h / 2, b.y + b.h / 2) - Math.max(a.y - a.h / 2, b.y - b.h / 2);
  return w > 0 && h > 0 ? w * h : 0;
}

/** Places the value chips (near each source) and then the name chips (near each target), where they cover the least. */
function placeLabels(arcs: DiagramArc[], nodes: MNode[], headers: readonly Box[], width: number): ValueChip[] {
  const solid: Box[] = nodes.filter((n) => n.kind !== 'dummy').map((n) => ({ x: n.x, y: n.y, w: n.w + 4, h: n.h + 4 }));
  const placed: Box[] = [];
  const best = (size: { w: number; h: number }, candidates: { seg: Segment; ts: readonly number[]; penalty: number }[]): Box => {
    let found: Box | null = null;
    let bestScore = Infinity;
    for (const { seg, ts, penalty } of candidates) {
      ts.forEach((t, k) => {
        const p = pointOn(seg, t);
        for (const side of [0, -1, 1]) {
          const x = Math.min(width - size.w / 2 - 1, Math.max(size.w / 2 + 1, p.x + side * (size.w / 2 + 3)));
          const box = { x, y: p.y, w: size.w, h: size.h };
          let score = penalty + k * 2 + Math.abs(side) * 14 + Math.abs(x - p.x - side * (size.w / 2 + 3)) * 2;
          for (const s of solid) score += overlap(box, s) * 10;
          for (const s of headers) score += overlap(box, s) * 3;
          for (const s of placed) score += overlap(box, s) * 2;
          if (score < bestScore) {
            bestScore = score;
            found = box;
          }
        }
      });
    }
    placed.push(found!);
    return found!;
  };

  // Values: one chip per source and trunk, near the source.
  const groups = new Map<string, DiagramArc[]>();
  for (const a of arcs) {
    if (a.input === null) continue;
    const first = a.points[1];
    const dir = first.y < a.points[0].y - 1 ? 'up' : first.y > a.points[0].y + 1 ? 'down' : 'side';
    const k = `${a.from}|${dir}`;
    if (!groups.has(k)) groups.set(k, []);
    groups.get(k)!.push(a);
  }
  const near = [0.3, 0.45, 0.2, 0.6, 0.75, 0.12];
  const values: ValueChip[] = [...groups.values()].map((group) => {
    const shared = group.every((a) => a.points.length > 2) && group.every((a) => a.points[1].x === group[0].points[1].x && a.points[1].y === group[0].points[1].y);
    const candidates = shared ? [{ seg: group[0].segments[0], ts: near, penalty: 0 }, ...(group[0].segments[1] ? [{ seg: group[0].segments[1], ts: near, penalty: 25 }] : [])] : group.map((a, i) => ({ seg: a.segments[0], ts: near, penalty: i }));
    return { source: group[0].source, node: group[0].from, arcs: group.map((a) => a.id), box: best(VALUE_CHIP, candidates) };
  });

  // Names: near the target, crowded targets first so their many names get the best places.
  const labelled = arcs.filter((a) => a.input !== null);
  const count = new Map<string, number>();
  for (const a of labelled) count.set(a.to, (count.get(a.to) ?? 0) + 1);
  labelled.sort((a, b) => (count.get(b.to) ?? 0) - (count.get(a.to) ?? 0));
  const ts = [0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9];
  for (const a of labelled) {
    const n = a.segments.length;
    const candidates = [0, 1, 2].filter((back) => back < n).map((back) => ({ seg: a.segments[n - 1 - back], ts, penalty: back * 30 }));
    (a as { label: Box | null }).label = best(chipSize(a.input!), candidates);
  }
  return values;
}
