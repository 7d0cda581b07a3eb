/**
 * The Diagram pane: the controller drawn as the original design draws it (layers as bands,
 * functions as ovals, arcs as arrows, previous-tick arcs through matching ports on the layer
 * edges, the world inputs below, the body command at the bottom), as SVG. At the selected tick
 * every arc shows its value. Clicking a function opens its blocks. Layout: `layout.ts`.
 */
import './diagram.css';
import type { ControllerSpec } from '../../core/controller/model';
import type { ControllerError } from '../../core/session/types';
import type { ArcRow } from '../engine/client';
import type { ControllerPane, PaneHost } from '../panes/types';
import type { DiagramArc, DiagramLayout, DiagramNode, ValueChip } from './layout';
import { layoutController } from './layout';
import { fullArcValue, shortArcValue } from './values';

const SVG = 'http://www.w3.org/2000/svg';

function svg<K extends keyof SVGElementTagNameMap>(tag: K, attrs: Record<string, string | number>, parent?: Element): SVGElementTagNameMap[K] {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  parent?.appendChild(e);
  return e;
}

function html<K extends keyof HTMLElementTagNameMap>(tag: K, className?: string, text?: string): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  if (className) e.className = className;
  if (text !== undefined) e.textContent = text;
  return e;
}

function title(parent: Element, text: string): SVGTitleElement {
  const t = svg('title', {}, parent);
  t.textContent = text;
  return t;
}

/** What decides the drawing (not the function bodies): a new one means a new layout. */
function shapeOf(spec: ControllerSpec): string {
  return JSON.stringify([
    spec.bodyCommand,
    spec.layers.map((l) => [l.name, l.variables, l.randomSources.map((r) => r.name), l.functions.map((f) => [f.name, f.output, f.inputs])]),
  ]);
}

const key = (fn: string, input: string): string => `${fn}\u0000${input}`;

interface ArcView {
  arc: DiagramArc;
  group: SVGGElement;
  path: SVGPathElement;
  tip: SVGTitleElement;
  chip: SVGGElement | null;
  chipTip: SVGTitleElement | null;
}

interface ValueView {
  chip: ValueChip;
  group: SVGGElement;
  rect: SVGRectElement;
  text: SVGTextElement;
  tip: SVGTitleElement;
}

/** The controller diagram pane. */
export function diagramPane(): ControllerPane {
  return new DiagramPane();
}

class DiagramPane implements ControllerPane {
  readonly id = 'diagram';
  readonly title = 'Diagram';
  private host!: PaneHost;
  private root!: HTMLElement;
  private svgEl!: SVGSVGElement;
  private viewport!: SVGGElement;
  private empty!: HTMLElement;
  private tickLabel!: HTMLElement;
  private menu: HTMLElement | null = null;

  private spec: ControllerSpec | null = null;
  private shape = '';
  private layout: DiagramLayout | null = null;
  private arcViews: ArcView[] = [];
  private valueViews: ValueView[] = [];
  private fnViews = new Map<string, SVGGElement>();

  private visible = false;
  private rows = new Map<string, ArcRow>();
  private rowsTick = -1;
  private asking = false;
  private askedAt = 0;
  private error: ControllerError | null = null;
  private selected: string | null = null;

  private scale = 1;
  private tx = 0;
  private ty = 0;
  private userMoved = false;
  private fitPending = true;

  mount(element: HTMLElement, host: PaneHost): void {
    this.host = host;
    this.root = html('div', 'diagram');
    this.root.tabIndex = -1;
    element.appendChild(this.root);
    this.svgEl = svg('svg', { class: 'dg-svg', role: 'img', 'aria-label': 'Controller diagram' }, this.root);
    this.defs();
    this.viewport = svg('g', { class: 'dg-viewport' }, this.svgEl);

    const bar = html('div', 'dg-bar');
    this.tickLabel = html('span', 'dg-tick', '');
    const zoomOut = html('button', 'dg-btn', '−');
    zoomOut.title = 'Zoom out (-)';
    const zoomIn = html('button', 'dg-btn', '+');
    zoomIn.title = 'Zoom in (+)';
    const fit = html('button', 'dg-btn dg-fit', 'Fit');
    fit.title = 'Fit the diagram to the pane (0)';
    zoomOut.addEventListener('click', () => this.zoomBy(1 / 1.25));
    zoomIn.addEventListener('click', () => this.zoomBy(1.25));
    fit.addEventListener('click', () => this.fit());
    bar.append(this.tickLabel, zoomOut, zoomIn, fit);
    this.root.appendChild(bar);
    this.empty = html('div', 'empty-state dg-empty');
    this.root.appendChild(this.empty);

    this.wireInput();
    new ResizeObserver(() => {
      if (!this.userMoved || this.fitPending) this.fit();
      else this.applyView();
    }).observe(this.root);

    host.onControllerOpened((spec) => this.setController(spec, true));
    host.onTickSelected(() => {
      this.syncController();
      this.refreshValues();
    });
    host.onError((e) => {
      this.error = e;
      this.applyError();
    });
    this.setController(host.controller(), true);
  }

  shown(): void {
    this.visible = true;
    this.syncController();
    if (this.fitPending || !this.userMoved) this.fit();
    this.refreshValues();
  }

  hidden(): void {
    this.visible = false;
    this.closeMenu();
  }

  /** The editor opened a function elsewhere: show it selected here too. */
  openFunction(_layer: string, fn: string): boolean {
    this.select(fn);
    return false;
  }

  // ---------------------------------------------------------------- the drawing

  private syncController(): void {
    const spec = this.host.controller();
    if (spec !== this.spec) this.setController(spec, false);
  }

  private setController(spec: ControllerSpec | null, opened: boolean): void {
    this.spec = spec;
    const shape = spec ? shapeOf(spec) : '';
    if (shape === this.shape && this.layout) return;
    this.shape = shape;
    if (opened) {
      this.selected = null;
      this.userMoved = false;
    }
    this.rows = new Map();
    this.rowsTick = -1;
    this.build();
    this.fitPending = true;
    if (this.visible) this.fit();
    this.refreshValues();
  }

  private build(): void {
    this.viewport.replaceChildren();
    this.arcViews = [];
    this.valueViews = [];
    this.fnViews.clear();
    this.layout = null;
    const spec = this.spec;
    if (!spec || spec.layers.length === 0) {
      this.empty.hidden = false;
      this.empty.replaceChildren();
      const box = html('div');
      box.append(html('b', undefined, spec ? 'This controller has no layers' : 'No controller is open'), spec ? 'Add a layer in the Blocks view to see it here.' : 'Open a controller from the File menu to see its diagram.');
      this.empty.appendChild(box);
      this.svgEl.style.display = 'none';
      return;
    }
    this.empty.hidden = true;
    this.svgEl.style.display = '';
    let layout: DiagramLayout;
    try {
      layout = layoutController(spec);
    } catch (e) {
      this.empty.hidden = false;
      this.empty.textContent = `The diagram could not be drawn: ${e instanceof Error ? e.message : String(e)}`;
      return;
    }
    this.layout = layout;
    const v = this.viewport;
    const bandsG = svg('g', { class: 'dg-bands' }, v);
    const arcsG = svg('g', { class: 'dg-arcs' }, v);
    const nodesG = svg('g', { class: 'dg-nodes' }, v);
    const chipsG = svg('g', { class: 'dg-chips' }, v);

    layout.bands.forEach((b) => {
      const g = svg('g', { class: `dg-band${b.index % 2 ? ' dg-band-alt' : ''}`, 'data-layer': b.layer, 'data-index': b.index }, bandsG);
      svg('rect', { class: 'dg-band-rect', x: b.x, y: b.y + 2, width: b.w, height: b.h - 4, rx: 8 }, g);
      const t = svg('text', { class: 'dg-band-title', x: b.x + 12, y: b.titleY }, g);
      t.textContent = b.layer;
      b.variables.forEach((line, i) => {
        const vt = svg('text', { class: 'dg-band-vars', x: b.x + 12, y: b.firstVariableY + i * 13 }, g);
        vt.textContent = line;
      });
    });
    if (layout.world) {
      const w = layout.world;
      const g = svg('g', { class: 'dg-world-row' }, bandsG);
      svg('rect', { class: 'dg-world-rect', x: w.x, y: w.y + 2, width: w.w, height: w.h - 4, rx: 8 }, g);
      const t = svg('text', { class: 'dg-world-title', x: w.x + 12, y: w.titleY }, g);
      t.textContent = 'World and body';
    }

    for (const arc of layout.arcs) this.arcViews.push(this.drawArc(arc, arcsG, chipsG));
    for (const n of layout.nodes) this.drawNode(n, nodesG);
    const valuesG = svg('g', { class: 'dg-values' }, v);
    for (const chip of layout.values) {
      const g = svg('g', { class: 'dg-value', 'data-source': chip.source, 'data-node': chip.node }, valuesG);
      const rect = svg('rect', { class: 'dg-value-rect', rx: 7.5, y: chip.box.y - chip.box.h / 2, height: chip.box.h }, g);
      const text = svg('text', { class: 'dg-value-text', x: chip.box.x, y: chip.box.y + 3.5, 'text-anchor': 'middle' }, g);
      const tip = title(g, '');
      this.valueViews.push({ chip, group: g, rect, text, tip });
    }
    this.applyValues();
    this.applyError();
    this.applySelection();
  }

  private defs(): void {
    const defs = svg('defs', {}, this.svgEl);
    for (const [id, cls] of [
      ['dg-arrow', 'dg-head'],
      ['dg-arrow-world', 'dg-head dg-head-world'],
      ['dg-arrow-hot', 'dg-head dg-head-hot'],
      ['dg-arrow-changed', 'dg-head dg-head-changed'],
    ]) {
      const m = svg('marker', { id, viewBox: '0 0 10 10', refX: 9, refY: 5, markerWidth: 6.5, markerHeight: 6.5, markerUnits: 'userSpaceOnUse', orient: 'auto' }, defs);
      m.setAttribute('markerWidth', '8');
      m.setAttribute('markerHeight', '8');
      svg('path', { d: 'M0,1 L10,5 L0,9 z', class: cls }, m);
    }
  }

  private drawArc(arc: DiagramArc, arcsG: SVGGElement, chipsG: SVGGElement): ArcView {
    const g = svg('g', { class: `dg-arc dg-arc-${arc.kind}`, 'data-from': arc.from, 'data-to': arc.to, 'data-source': arc.source }, arcsG);
    if (arc.input) g.dataset.input = arc.input;
    if (arc.target) g.dataset.target = arc.target;
    svg('path', { class: 'dg-arc-hit', d: arc.path }, g);
    const path = svg('path', { class: 'dg-arc-line', d: arc.path }, g);
    const tip = title(g, this.arcTitle(arc, undefined, false));
    const view: ArcView = { arc, group: g, path, tip, chip: null, chipTip: null };
    this.setMarker(view, false);
    const l = arc.label;
    if (l && arc.input) {
      const c = svg('g', { class: 'dg-chip', 'data-target': arc.target ?? '', 'data-input': arc.input, 'data-from': arc.from }, chipsG);
      svg('rect', { class: 'dg-chip-rect', rx: 3, x: l.x - l.w / 2, y: l.y - l.h / 2, width: l.w, height: l.h }, c);
      const name = svg('text', { class: 'dg-chip-name', x: l.x, y: l.y + 3.3, 'text-anchor': 'middle' }, c);
      name.textContent = arc.input;
      view.chipTip = title(c, '');
      view.chip = c;
    }
    return view;
  }

  private setMarker(view: ArcView, changed: boolean): void {
    const kind = view.arc.kind;
    const id = changed ? 'dg-arrow-changed' : kind === 'world' || kind === 'random' ? 'dg-arrow-world' : 'dg-arrow';
    view.path.setAttribute('marker-end', kind === 'previous-out' ? '' : `url(#${id})`);
  }

  private arcTitle(arc: DiagramArc, row: ArcRow | undefined, haveValues: boolean): string {
    const from = arc.source.startsWith('previous.')
      ? `${arc.source.slice(9)} from the previous tick (matching ports)`
      : arc.source.startsWith('world.')
        ? `the world input ${arc.source.slice(6)}`
        : arc.source.startsWith('random.')
          ? `the random source ${arc.source.slice(7)}`
          : arc.source;
    let text: string;
    if (arc.kind === 'previous-out') text = `${arc.source} → its output port: the value passes to the next tick`;
    else if (arc.kind === 'body') text = `${arc.source} → the body: the body command {heading, dx, dy}`;
    else text = `${arc.input} of ${arc.target} ← ${from}`;
    if (row && haveValues) text += `\nvalue at tick ${this.rowsTick}: ${fullArcValue(row.value)}${row.changed ? '\n(changed since the tick before)' : ''}`;
    return text;
  }

  private drawNode(n: DiagramNode, parent: SVGGElement): void {
    if (n.kind === 'function') {
      const g = svg('g', { class: `dg-fn${n.bodyCommand ? ' dg-body-command' : ''}`, 'data-function': n.function!, 'data-layer': n.layer!, tabindex: 0, role: 'button' }, parent);
      g.setAttribute('aria-label', `Function ${n.function} (layer ${n.layer}). Enter opens its blocks; the context menu steps into it.`);
      if (n.bodyCommand) svg('ellipse', { class: 'dg-fn-outer', cx: n.x, cy: n.y, rx: n.w / 2 + 4, ry: n.h / 2 + 4 }, g);
      svg('ellipse', { class: 'dg-fn-shape', cx: n.x, cy: n.y, rx: n.w / 2, ry: n.h / 2 }, g);
      const t = svg('text', { class: 'dg-fn-name', x: n.x, y: n.y + 4.5, 'text-anchor': 'middle' }, g);
      t.textContent = n.label;
      const fn = this.spec?.layers.flatMap((l) => l.functions).find((f) => f.name === n.function);
      title(g, `${n.function} (layer ${n.layer}) → ${fn?.output ?? '?'}${fn?.description ? `\n${fn.description}` : ''}${n.bodyCommand ? '\nIts output is the body command.' : ''}\nClick to open its blocks; right-click to step into it.`);
      this.fnViews.set(n.function!, g);
    } else if (n.kind === 'port-in' || n.kind === 'port-out') {
      const s = n.w;
      const g = svg('g', { class: `dg-port dg-${n.kind}`, 'data-function': n.function!, 'data-layer': n.layer ?? '' }, parent);
      svg('rect', { x: n.x - s / 2, y: n.y - s / 2, width: s, height: s, rx: 1.5 }, g);
      title(g, n.kind === 'port-in' ? `Input port: ${n.function} from the previous tick` : `Output port: ${n.function}, passed to the next tick`);
    } else {
      const cls = n.kind === 'world' ? 'dg-world' : n.kind === 'random' ? 'dg-random' : 'dg-body';
      const g = svg('g', { class: `dg-box ${cls}`, 'data-node': n.id }, parent);
      if (n.kind === 'world') g.dataset.input = n.label;
      if (n.kind === 'random') g.dataset.source = n.label;
      svg('rect', { x: n.x - n.w / 2, y: n.y - n.h / 2, width: n.w, height: n.h, rx: n.kind === 'body' ? n.h / 2 : 4 }, g);
      let tx = n.x;
      if (n.kind === 'random') {
        // A small die: a random source.
        const dx = n.x - n.w / 2 + 6;
        svg('rect', { class: 'dg-die', x: dx, y: n.y - 4.5, width: 9, height: 9, rx: 2 }, g);
        svg('circle', { class: 'dg-die-dot', cx: dx + 3, cy: n.y - 1.5, r: 1.1 }, g);
        svg('circle', { class: 'dg-die-dot', cx: dx + 6, cy: n.y + 1.5, r: 1.1 }, g);
        tx += 7;
      }
      const t = svg('text', { class: 'dg-box-label', x: tx, y: n.y + 4, 'text-anchor': 'middle' }, g);
      t.textContent = n.label;
      const spec = this.spec;
      const random = n.kind === 'random' ? spec?.layers.flatMap((l) => l.randomSources).find((r) => r.name === n.label) : undefined;
      title(
        g,
        n.kind === 'world'
          ? `World input ${n.label}`
          : n.kind === 'random'
            ? `Random source ${n.label}${random ? ` (${random.type}, seed ${random.seed})` : ''}`
            : `The body: ${spec?.bodyCommand}'s output {heading, dx, dy} moves the robot`,
      );
    }
  }

  // ---------------------------------------------------------------- values, errors, selection

  private refreshValues(): void {
    const tick = this.host.selectedTick();
    this.tickLabel.textContent = `Tick ${tick}`;
    if (!this.visible || !this.layout) return;
    if (tick === this.rowsTick || this.asking) return;
    if (tick === 0) {
      this.rows = new Map();
      this.rowsTick = 0;
      this.applyValues();
      this.applyError();
      return;
    }
    // While running, a few updates a second are plenty to read.
    const wait = 90 - (performance.now() - this.askedAt);
    if (wait > 0) {
      this.asking = true;
      setTimeout(() => {
        this.asking = false;
        this.refreshValues();
      }, wait);
      return;
    }
    this.asking = true;
    this.askedAt = performance.now();
    void this.host.arcs(tick).then(
      (rows) => {
        this.asking = false;
        this.rows = new Map(rows.map((r) => [key(r.to, r.input), r]));
        this.rowsTick = tick;
        this.applyValues();
        this.applyError();
        if (this.host.selectedTick() !== tick) this.refreshValues();
      },
      () => {
        this.asking = false;
      },
    );
  }

  private applyValues(): void {
    const have = this.rowsTick > 0 && this.rows.size > 0;
    this.root.classList.toggle('dg-has-values', have);
    for (const view of this.arcViews) {
      const a = view.arc;
      const row = have && a.target && a.input ? this.rows.get(key(a.target, a.input)) : undefined;
      const changed = !!row?.changed;
      view.group.classList.toggle('dg-changed', changed);
      view.chip?.classList.toggle('dg-changed', changed);
      this.setMarker(view, changed);
      view.tip.textContent = this.arcTitle(a, row, have);
      if (view.chipTip) view.chipTip.textContent = this.arcTitle(a, row, have);
    }
    const bySource = new Map<string, ArcRow>();
    if (have) for (const r of this.rows.values()) if (!bySource.has(r.from)) bySource.set(r.from, r);
    for (const v of this.valueViews) {
      const row = bySource.get(v.chip.source);
      v.group.style.display = row ? '' : 'none';
      if (!row) continue;
      const text = shortArcValue(row.value);
      v.text.textContent = text;
      const w = Math.max(22, text.length * 6.1 + 10);
      v.rect.setAttribute('x', String(v.chip.box.x - w / 2));
      v.rect.setAttribute('width', String(w));
      v.group.classList.toggle('dg-changed', row.changed);
      v.tip.textContent = `${v.chip.source.replace(/^previous\./, '').replace(/^world\./, 'world input ').replace(/^random\./, 'random source ')}${v.chip.source.startsWith('previous.') ? ' at the previous tick' : ''} = ${fullArcValue(row.value)}${row.changed ? '\n(changed since the tick before)' : ''}`;
    }
  }

  private applyError(): void {
    const e = this.error;
    const tick = this.host.selectedTick();
    const fn = e && e.function && e.tick === tick ? e.function : null;
    for (const [name, g] of this.fnViews) {
      const on = name === fn;
      g.classList.toggle('dg-error', on);
      const t = g.querySelector('title');
      if (t) {
        const base = (t.textContent ?? '').split('\n⚠ ')[0];
        t.textContent = on && e ? `${base}\n⚠ ${e.message}` : base;
      }
    }
  }

  private select(fn: string | null): void {
    this.selected = fn;
    this.applySelection();
  }

  private applySelection(): void {
    for (const [name, g] of this.fnViews) g.classList.toggle('dg-selected', name === this.selected);
  }

  /** Emphasises a node's arcs (hover or focus); null clears it. */
  private focusNode(id: string | null): void {
    this.root.classList.toggle('dg-focusing', id !== null);
    for (const v of this.arcViews) {
      const hot = id !== null && (v.arc.from === id || v.arc.to === id || (id.startsWith('fn:') && (v.arc.from === `in:${id.slice(3)}` || v.arc.to === `out:${id.slice(3)}`)));
      v.group.classList.toggle('dg-hot', hot);
      v.chip?.classList.toggle('dg-hot', hot);
      if (hot) v.path.setAttribute('marker-end', v.arc.kind === 'previous-out' ? '' : 'url(#dg-arrow-hot)');
      else this.setMarker(v, v.group.classList.contains('dg-changed'));
    }
    for (const v of this.valueViews) v.group.classList.toggle('dg-hot', v.chip.arcs.some((id) => this.arcViews.some((a) => a.arc.id === id && a.group.classList.contains('dg-hot'))));
  }

  private open(layer: string, fn: string): void {
    this.select(fn);
    const opened = this.host.openFunction(layer, fn);
    if (!opened) this.host.showPane('blocks');
  }

  // ---------------------------------------------------------------- input: click, menu, pan, zoom

  private fnTarget(t: EventTarget | null): SVGGElement | null {
    return t instanceof Element ? (t.closest('.dg-fn') as SVGGElement | null) : null;
  }

  private nodeTarget(t: EventTarget | null): string | null {
    if (!(t instanceof Element)) return null;
    const fn = t.closest<SVGGElement>('.dg-fn');
    if (fn) return `fn:${fn.dataset.function}`;
    const box = t.closest<SVGGElement>('.dg-box');
    if (box) return box.dataset.node ?? null;
    const port = t.closest<SVGGElement>('.dg-port');
    if (port) return `fn:${port.dataset.function}`;
    return null;
  }

  private wireInput(): void {
    const s = this.svgEl;
    let drag: { id: number; x: number; y: number; tx: number; ty: number; moved: boolean; fn: SVGGElement | null } | null = null;
    s.addEventListener('pointerdown', (e) => {
      if (e.button !== 0) return;
      this.closeMenu();
      drag = { id: e.pointerId, x: e.clientX, y: e.clientY, tx: this.tx, ty: this.ty, moved: false, fn: this.fnTarget(e.target) };
    });
    s.addEventListener('pointermove', (e) => {
      if (!drag || e.pointerId !== drag.id) {
        if (!drag) this.focusNode(this.nodeTarget(e.target));
        return;
      }
      const dx = e.clientX - drag.x;
      const dy = e.clientY - drag.y;
      if (!drag.moved && Math.hypot(dx, dy) < 4) return;
      if (!drag.moved) {
        drag.moved = true;
        s.setPointerCapture(e.pointerId);
        this.root.classList.add('dg-panning');
      }
      this.tx = drag.tx + dx;
      this.ty = drag.ty + dy;
      this.userMoved = true;
      this.applyView();
    });
    const end = (e: PointerEvent): void => {
      if (!drag || e.pointerId !== drag.id) return;
      const d = drag;
      drag = null;
      this.root.classList.remove('dg-panning');
      if (s.hasPointerCapture(e.pointerId)) s.releasePointerCapture(e.pointerId);
      if (!d.moved && d.fn && e.type === 'pointerup') this.open(d.fn.dataset.layer!, d.fn.dataset.function!);
    };
    s.addEventListener('pointerup', end);
    s.addEventListener('pointercancel', end);
    s.addEventListener('pointerleave', () => {
      if (!drag) this.focusNode(null);
    });
    s.addEventListener('dblclick', (e) => {
      if (!this.fnTarget(e.target)) this.fit();
    });
    s.addEventListener(
      'wheel',
      (e) => {
        e.preventDefault();
        const r = s.getBoundingClientRect();
        const delta = e.deltaMode === 1 ? e.deltaY * 16 : e.deltaY;
        this.zoomBy(Math.exp(-delta * 0.0015), e.clientX - r.left, e.clientY - r.top);
      },
      { passive: false },
    );
    s.addEventListener('contextmenu', (e) => {
      const fn = this.fnTarget(e.target);
      e.preventDefault();
      this.openMenu(fn, e.clientX, e.clientY);
    });
    s.addEventListener('focusin', (e) => this.focusNode(this.nodeTarget(e.target)));
    s.addEventListener('focusout', () => this.focusNode(null));
    this.root.addEventListener('keydown', (e) => {
      const fn = this.fnTarget(e.target);
      if (e.key === 'Escape' && this.menu) {
        this.closeMenu();
        e.preventDefault();
        return;
      }
      if (fn && (e.key === 'Enter' || e.key === ' ')) {
        e.preventDefault();
        this.open(fn.dataset.layer!, fn.dataset.function!);
      } else if (fn && (e.key === 'ContextMenu' || (e.shiftKey && e.key === 'F10'))) {
        e.preventDefault();
        const r = fn.getBoundingClientRect();
        this.openMenu(fn, r.left + r.width / 2, r.bottom);
      } else if (e.key === '+' || e.key === '=') this.zoomBy(1.25);
      else if (e.key === '-') this.zoomBy(1 / 1.25);
      else if (e.key === '0') this.fit();
      else return;
      e.stopPropagation();
    });
  }

  private openMenu(fn: SVGGElement | null, clientX: number, clientY: number): void {
    this.closeMenu();
    const menu = html('div', 'dg-menu');
    menu.setAttribute('role', 'menu');
    const item = (label: string, action: () => void, disabled = false): void => {
      const b = html('button', 'dg-menu-item', label);
      b.setAttribute('role', 'menuitem');
      b.disabled = disabled;
      b.addEventListener('click', () => {
        this.closeMenu();
        action();
      });
      menu.appendChild(b);
    };
    if (fn) {
      const layer = fn.dataset.layer!;
      const name = fn.dataset.function!;
      this.select(name);
      const head = html('div', 'dg-menu-head', name);
      menu.appendChild(head);
      item('Open blocks', () => this.open(layer, name));
      const tick = this.host.selectedTick();
      item(tick > 0 ? `Step into at tick ${tick}` : 'Step into at this tick', () => this.host.stepInto(layer, name), tick === 0);
    }
    item('Fit to pane', () => this.fit());
    const r = this.root.getBoundingClientRect();
    menu.style.left = `${Math.min(clientX - r.left, r.width - 190)}px`;
    menu.style.top = `${Math.min(clientY - r.top, r.height - 110)}px`;
    this.root.appendChild(menu);
    this.menu = menu;
    menu.querySelector<HTMLButtonElement>('button:not(:disabled)')?.focus();
    const away = (e: PointerEvent): void => {
      if (!menu.contains(e.target as Node)) this.closeMenu();
    };
    setTimeout(() => document.addEventListener('pointerdown', away, { capture: true, once: true }));
  }

  private closeMenu(): void {
    this.menu?.remove();
    this.menu = null;
  }

  private fit(): void {
    const l = this.layout;
    const w = this.root.clientWidth;
    const h = this.root.clientHeight;
    if (!l || w === 0 || h === 0) {
      this.fitPending = true;
      return;
    }
    const pad = 12;
    const top = 36; // room for the zoom buttons
    const scale = Math.min((w - 2 * pad) / l.width, (h - top - pad) / l.height, 1.5);
    this.scale = Math.max(0.15, scale);
    this.tx = (w - l.width * this.scale) / 2;
    this.ty = top + Math.max(0, (h - top - pad - l.height * this.scale) / 2);
    this.userMoved = false;
    this.fitPending = false;
    this.applyView();
  }

  private zoomBy(factor: number, cx?: number, cy?: number): void {
    const x = cx ?? this.root.clientWidth / 2;
    const y = cy ?? this.root.clientHeight / 2;
    const next = Math.min(4, Math.max(0.15, this.scale * factor));
    const k = next / this.scale;
    this.tx = x - (x - this.tx) * k;
    this.ty = y - (y - this.ty) * k;
    this.scale = next;
    this.userMoved = true;
    this.applyView();
  }

  private applyView(): void {
    this.viewport.setAttribute('transform', `translate(${this.tx.toFixed(1)},${this.ty.toFixed(1)}) scale(${this.scale.toFixed(4)})`);
    this.root.dataset.zoom = this.scale.toFixed(3);
  }
}
