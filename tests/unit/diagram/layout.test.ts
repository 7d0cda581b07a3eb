/** The diagram's layout: bands, ovals, ports, the world row and the routes, for every example controller. */
import { readdirSync } from 'node:fs';
import { join } from 'node:path';
import type { ControllerSpec } from '../../../app/core/controller/model';
import { allFunctions } from '../../../app/core/controller/model';
import type { Box, DiagramLayout, DiagramNode } from '../../../app/renderer/diagram/layout';
import { layoutController, pointOn } from '../../../app/renderer/diagram/layout';
import { shortArcValue } from '../../../app/renderer/diagram/values';
import { exampleController, ROOT } from '../../support/examples';

const EXAMPLES = readdirSync(join(ROOT, 'examples', 'controllers'))
  .filter((f) => f.endsWith('.controller.json'))
  .map((f) => f.replace(/\.controller\.json$/, ''))
  .sort();

function overlaps(a: Box, b: Box, margin = 0): boolean {
  return Math.abs(a.x - b.x) < (a.w + b.w) / 2 + margin && Math.abs(a.y - b.y) < (a.h + b.h) / 2 + margin;
}

/** True when a point is inside an oval (shrunk a little, so touching the outline does not count). */
function insideOval(n: DiagramNode, x: number, y: number): boolean {
  const rx = n.w / 2 - 2;
  const ry = n.h / 2 - 2;
  return ((x - n.x) / rx) ** 2 + ((y - n.y) / ry) ** 2 < 1;
}

test('there are example controllers to lay out', () => {
  expect(EXAMPLES).toEqual(expect.arrayContaining(['basic', 'value-iteration']));
});

describe.each(EXAMPLES)('the %s controller', (name) => {
  let spec: ControllerSpec;
  let layout: DiagramLayout;
  beforeAll(() => {
    spec = exampleController(name);
    layout = layoutController(spec);
  });
  const fnNode = (fn: string): DiagramNode => layout.nodes.find((n) => n.id === `fn:${fn}`)!;

  test('has a band per layer, top layer first, stacked without gaps or overlaps', () => {
    expect(layout.bands.map((b) => b.layer)).toEqual(spec.layers.map((l) => l.name));
    for (let i = 1; i < layout.bands.length; i++) {
      const above = layout.bands[i - 1];
      expect(layout.bands[i].y).toBeCloseTo(above.y + above.h);
    }
    for (const b of layout.bands) expect(b.w).toBe(layout.width);
  });

  test('draws every function as an oval inside its layer band', () => {
    for (const { fn, layer } of allFunctions(spec)) {
      const n = fnNode(fn.name);
      expect(n).toBeDefined();
      expect(n.kind).toBe('function');
      expect(n.layer).toBe(layer.name);
      const band = layout.bands.find((b) => b.layer === layer.name)!;
      expect(n.y - n.h / 2).toBeGreaterThan(band.y);
      expect(n.y + n.h / 2).toBeLessThan(band.y + band.h);
      expect(n.x - n.w / 2).toBeGreaterThan(band.x);
      expect(n.x + n.w / 2).toBeLessThan(band.x + band.w);
    }
    expect(layout.nodes.filter((n) => n.kind === 'function')).toHaveLength(allFunctions(spec).length);
  });

  test('no two ovals or boxes overlap, and nothing leaves the drawing', () => {
    const solid = layout.nodes.filter((n) => n.kind !== 'port-in' && n.kind !== 'port-out');
    for (let i = 0; i < solid.length; i++) {
      for (let j = i + 1; j < solid.length; j++) expect([solid[i].id, solid[j].id, overlaps(solid[i], solid[j], 4)]).toEqual([solid[i].id, solid[j].id, false]);
    }
    for (const n of layout.nodes) {
      expect(n.x - n.w / 2).toBeGreaterThanOrEqual(-n.w);
      expect(n.x + n.w / 2).toBeLessThanOrEqual(layout.width + n.w);
      expect(n.y + n.h / 2).toBeLessThanOrEqual(layout.height);
    }
  });

  test('orders each band by dependency: a function sits below the functions of its band it reads this tick', () => {
    for (const { fn, layer } of allFunctions(spec)) {
      for (const inp of fn.inputs) {
        if (inp.from.kind !== 'function') continue;
        const src = inp.from.function;
        if (!layer.functions.some((f) => f.name === src)) continue;
        expect([src, fn.name, fnNode(src).y < fnNode(fn.name).y]).toEqual([src, fn.name, true]);
      }
    }
  });

  test('routes previous-tick arcs through matching ports on the edges of the source layer', () => {
    const previous = new Set(allFunctions(spec).flatMap(({ fn }) => fn.inputs.flatMap((i) => (i.from.kind === 'previous' ? [i.from.function] : []))));
    expect(previous.size).toBeGreaterThan(0);
    for (const fn of previous) {
      const pin = layout.nodes.find((n) => n.id === `in:${fn}`)!;
      const pout = layout.nodes.find((n) => n.id === `out:${fn}`)!;
      expect(pin.kind).toBe('port-in');
      expect(pout.kind).toBe('port-out');
      // Matching ports: the same height, on the left and right edges of the source's band.
      expect(pin.y).toBeCloseTo(pout.y);
      const band = layout.bands.find((b) => b.layer === fnNode(fn).layer)!;
      expect(pin.x).toBeCloseTo(band.x);
      expect(pout.x).toBeCloseTo(band.x + band.w);
      expect(pin.y).toBeGreaterThan(band.y);
      expect(pin.y).toBeLessThan(band.y + band.h);
      expect(layout.arcs.filter((a) => a.kind === 'previous-out' && a.from === `fn:${fn}` && a.to === `out:${fn}`)).toHaveLength(1);
    }
    for (const { fn } of allFunctions(spec)) {
      for (const inp of fn.inputs) {
        if (inp.from.kind !== 'previous') continue;
        const arc = layout.arcs.find((a) => a.target === fn.name && a.input === inp.name)!;
        expect(arc.kind).toBe('previous-in');
        expect(arc.from).toBe(`in:${inp.from.function}`);
        expect(arc.source).toBe(`previous.${inp.from.function}`);
      }
    }
  });

  test('puts the world inputs in use in a row below the bottom band, and the body beside them', () => {
    const used = new Set(allFunctions(spec).flatMap(({ fn }) => fn.inputs.flatMap((i) => (i.from.kind === 'world' ? [i.from.input] : []))));
    const boxes = layout.nodes.filter((n) => n.kind === 'world');
    expect(new Set(boxes.map((b) => b.label))).toEqual(used);
    const last = layout.bands[layout.bands.length - 1];
    const body = layout.nodes.find((n) => n.kind === 'body')!;
    for (const b of [...boxes, body]) {
      expect(b.y - b.h / 2).toBeGreaterThan(last.y + last.h);
      expect(b.y).toBeCloseTo(body.y);
    }
    const bodyArc = layout.arcs.find((a) => a.kind === 'body')!;
    expect(bodyArc.from).toBe(`fn:${spec.bodyCommand}`);
    expect(fnNode(spec.bodyCommand).bodyCommand).toBe(true);
  });

  test('has an arc for every input, starting at its source and ending at its function', () => {
    for (const { fn } of allFunctions(spec)) {
      for (const inp of fn.inputs) {
        const arc = layout.arcs.find((a) => a.target === fn.name && a.input === inp.name);
        expect(arc).toBeDefined();
        const to = fnNode(fn.name);
        const end = arc!.points[arc!.points.length - 1];
        // The end lies on the oval's outline.
        expect(((end.x - to.x) / (to.w / 2)) ** 2 + ((end.y - to.y) / (to.h / 2)) ** 2).toBeCloseTo(1, 1);
        expect(arc!.label).not.toBeNull();
      }
    }
  });

  test('routes arcs around the ovals they do not connect', () => {
    const ovals = layout.nodes.filter((n) => n.kind === 'function');
    const crossings: string[] = [];
    for (const a of layout.arcs) {
      for (const s of a.segments) {
        for (let t = 0.02; t < 1; t += 0.02) {
          const p = pointOn(s, t);
          for (const o of ovals) {
            if (o.id === a.from || o.id === a.to) continue;
            if (insideOval(o, p.x, p.y)) crossings.push(`${a.id} crosses ${o.id}`);
          }
        }
      }
    }
    expect([...new Set(crossings)]).toEqual([]);
  });

  test('keeps label chips off the ovals', () => {
    const ovals = layout.nodes.filter((n) => n.kind === 'function');
    const bad = layout.arcs.filter((a) => a.label && ovals.some((o) => overlaps(a.label!, o, -2))).map((a) => a.id);
    expect(bad).toEqual([]);
  });

  test('is the same every time', () => {
    expect(layoutController(spec)).toEqual(layout);
  });
});

test('a controller being edited (unknown sources, a cycle, an empty layer) still lays out', () => {
  const fn = (name: string, inputs: ControllerSpec['layers'][number]['functions'][number]['inputs']) => ({ name, output: 'any' as const, inputs, body: { kind: 'text' as const, code: 'return 1;' } });
  const spec: ControllerSpec = {
    name: 'broken',
    bodyCommand: 'missing',
    layers: [
      { name: 'A', variables: [], randomSources: [{ name: 'coin', type: 'boolean', seed: 1 }], functions: [fn('a', [{ name: 'x', from: { kind: 'function', function: 'b' } }, { name: 'c', from: { kind: 'random', source: 'coin' } }])] },
      { name: 'Empty', variables: [], randomSources: [], functions: [] },
      { name: 'B', variables: [{ name: 'K', value: 3 }], randomSources: [], functions: [fn('b', [{ name: 'y', from: { kind: 'function', function: 'a' } }, { name: 'z', from: { kind: 'function', function: 'nobody' } }, { name: 'p', from: { kind: 'previous', function: 'ghost', initial: 0 } }])] },
    ],
  } as unknown as ControllerSpec;
  const layout = layoutController(spec);
  expect(layout.bands.map((b) => b.layer)).toEqual(['A', 'Empty', 'B']);
  expect(layout.nodes.filter((n) => n.kind === 'function').map((n) => n.label).sort()).toEqual(['a', 'b']);
  expect(layout.nodes.some((n) => n.kind === 'random' && n.label === 'coin')).toBe(true);
  expect(layout.arcs.map((a) => a.id).sort()).toEqual(['a/c', 'a/x', 'b/y']);
  expect(layout.nodes.some((n) => n.kind === 'body')).toBe(false);
});

test('short arc values fit a chip; long ones are summarised', () => {
  expect(shortArcValue(undefined)).toBe('—');
  expect(shortArcValue(3)).toBe('3');
  expect(shortArcValue(3.14159)).toBe('3.14');
  expect(shortArcValue(123.456)).toBe('123');
  expect(shortArcValue(true)).toBe('true');
  expect(shortArcValue('left')).toBe('"left"');
  expect(shortArcValue([2.5, 3])).toBe('[2.5,3]');
  expect(shortArcValue(['o109', 'storage', 'o103'])).toBe('[3 items]');
  expect(shortArcValue(Array.from({ length: 10 }, () => [1, 2, 3]))).toBe('grid 10×3');
  expect(shortArcValue({ heading: 90, dx: 0.5, dy: 0.866 })).toBe('{3 fields}');
  expect(shortArcValue('a very long string indeed').length).toBeLessThanOrEqual(14);
});
