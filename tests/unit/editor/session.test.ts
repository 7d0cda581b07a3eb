/** The editor's shared session: edits reach the app once, shortly after, or at once on flush. */
import type { ControllerSpec } from '../../../app/core/controller/model';
import type { EditRestrictions, PaneHost } from '../../../app/renderer/panes/types';
import { EditorSession } from '../../../app/renderer/editor/session';

const spec = (name: string): ControllerSpec => ({ name, bodyCommand: 'f', layers: [] });

function fakeHost(initial: ControllerSpec) {
  const opened: ((s: ControllerSpec | null) => void)[] = [];
  const restrictions: ((r: EditRestrictions | null) => void)[] = [];
  const updates: ControllerSpec[] = [];
  const host = {
    controller: () => initial,
    updateController: (s: ControllerSpec) => {
      updates.push(s);
      // The app announces every controller it loads, including ours.
      for (const fn of opened) fn(s);
    },
    onControllerOpened: (fn: (s: ControllerSpec | null) => void) => (opened.push(fn), () => undefined),
    restrictions: () => null,
    onRestrictionsChanged: (fn: (r: EditRestrictions | null) => void) => (restrictions.push(fn), () => undefined),
    onError: () => () => undefined,
  } as unknown as PaneHost;
  return { host, updates, open: (s: ControllerSpec | null) => opened.forEach((fn) => fn(s)), restrict: (r: EditRestrictions | null) => restrictions.forEach((fn) => fn(r)) };
}

describe('EditorSession', () => {
  beforeEach(() => jest.useFakeTimers());
  afterEach(() => jest.useRealTimers());

  test('edits are sent once after a pause, and our own controller coming back is no new document', () => {
    const { host, updates } = fakeHost(spec('a'));
    const s = new EditorSession();
    s.attach(host);
    s.attach(host);
    const origins: string[] = [];
    s.onSpec.on((o) => origins.push(o));
    s.setSpec(spec('b'), 'blocks');
    s.setSpec(spec('c'), 'blocks');
    expect(updates).toEqual([]);
    jest.advanceTimersByTime(1000);
    expect(updates.map((u) => u.name)).toEqual(['c']);
    expect(origins).toEqual(['blocks', 'blocks']);
  });

  test('flush sends at once; another controller opened replaces the pending edit', () => {
    const { host, updates, open, restrict } = fakeHost(spec('a'));
    const s = new EditorSession();
    s.attach(host);
    const origins: string[] = [];
    s.onSpec.on((o) => origins.push(o));
    s.setSpec(spec('b'), 'code');
    s.flush();
    expect(updates.map((u) => u.name)).toEqual(['b']);
    expect(s.pending).toBe(false);
    s.setSpec(spec('c'), 'blocks');
    open(spec('other'));
    jest.advanceTimersByTime(1000);
    expect(updates.map((u) => u.name)).toEqual(['b']);
    expect(s.spec?.name).toBe('other');
    expect(origins).toEqual(['code', 'blocks', 'host']);
    restrict({ locked: [{ layer: 'Top' }] });
    expect(s.restrictions?.locked).toEqual([{ layer: 'Top' }]);
  });
});
