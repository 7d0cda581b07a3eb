/**
 * The engine Worker's side of the app's watchdog (app/renderer/engine/host.ts): a new Worker
 * rebuilds the page's session, sends only the ticks the page lacks, and either records the error
 * the page found at the next tick, or goes on while reporting every call it starts.
 */
import { createPlainSandbox } from '../../../app/cli/bench/plain-sandbox';
import { EngineHost } from '../../../app/renderer/engine/host';
import type { EngineCommand, EngineEvent, TickFrame } from '../../../app/renderer/engine/protocol';
import { controller, fn, layer, world } from '../../support/controllers';

// The body command reads the tick, so it is called every tick (a call with the same inputs as the
// last is not made again, and a call not made cannot get stuck).
const c = controller([layer('Bottom', [fn('changePos', 'move', [{ name: 't', from: { kind: 'world', input: 'tick' } }], 'return { heading: 0, dx: 1, dy: 0 };')])]);

function host(): { h: EngineHost; events: EngineEvent[]; frames: () => TickFrame[] } {
  const events: EngineEvent[] = [];
  const h = new EngineHost(createPlainSandbox, (e) => events.push(e), () => 0, () => undefined);
  const frames = () => events.flatMap((e) => (e.type === 'ticks' ? e.frames : e.type === 'loaded' ? [e.frame] : []));
  return { h, events, frames };
}

const restore = (extra: Partial<Extract<EngineCommand, { type: 'restore' }>>): EngineCommand => ({
  type: 'restore',
  generation: 7,
  world,
  controller: c,
  bodies: {},
  upTo: 3,
  known: 1,
  edits: [],
  stopped: null,
  resume: null,
  ...extra,
});

test('the first Worker and a restored one give the same ticks', () => {
  const first = host();
  first.h.handle({ type: 'load', world, controller: c, bodies: {} });
  for (let i = 0; i < 3; i++) first.h.handle({ type: 'step' });
  const second = host();
  second.h.handle(restore({ stopped: { function: 'changePos', layer: 'Bottom', kind: 'resources', message: 'Error in function "changePos" (layer "Bottom"): stopped.' } }));
  const sent = second.frames();
  // Ticks 2 and 3 (the page had up to 1), then tick 4 with the error, the robot where it was.
  expect(sent.map((f) => f.tick)).toEqual([2, 3, 4]);
  expect(sent.slice(0, 2)).toEqual(first.frames().slice(2, 4));
  expect(sent[2].error?.message).toContain('stopped.');
  expect(sent[2].x).toBe(sent[1].x);
  const status = second.events.filter((e) => e.type === 'status').pop();
  expect(status).toMatchObject({ generation: 7, status: 'error', running: false });
});

test('without an error to record, the restored Worker computes the next tick reporting each call', () => {
  const { h, events, frames } = host();
  h.handle(restore({}));
  const calling = events.filter((e) => e.type === 'calling');
  expect(calling).toEqual([{ type: 'calling', generation: 7, tick: 4, index: 0 }]);
  expect(frames().map((f) => f.tick)).toEqual([2, 3, 4]);
});

test('edits are replayed at their ticks', () => {
  const { h, frames } = host();
  h.handle(restore({ upTo: 2, known: 0, edits: [{ tick: 1, edit: { type: 'moveRobot', x: 0, y: 5 } }] }));
  const f = frames();
  expect(f[0].edits.length).toBe(1);
  expect(f[1].y).toBeCloseTo(5);
});
