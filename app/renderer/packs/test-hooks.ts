/**
 * A window into the challenge packs for the browser tests (tests/e2e/packs.test.ts) and for
 * measuring Checks: what is open, each challenge's progress, and a few actions a test needs that
 * a person does with file pickers (open pack text, load a controller file's text).
 */
import { parseController } from '../../core/formats';
import type { App } from '../app/app';
import type { EditRestrictions } from '../panes/types';
import { packEditor } from './editor-pane';
import { checkDraft } from './draft';
import { progressOf } from './progress';
import type { PackSession } from './session';

export interface LayerbotPackTestHooks {
  state(): {
    pack: string | null;
    current: string | null;
    checking: boolean;
    preview: boolean;
    statuses: Record<string, string>;
    verdict: { passed: boolean; reasons: { criterion: string; world?: string; passed: boolean; detail: string }[] } | null;
    checks: { challenge: string; ms: number; passed: boolean }[];
    /** What the open challenge locks and offers, as the app applies it. */
    restrictions: EditRestrictions | null;
  };
  /** Opens pack text as File › Open pack… would. */
  openPackText(text: string, name: string): boolean;
  /** Loads a controller (file text) into the app, as File › Open… would; false when it cannot be read. */
  loadController(text: string): boolean;
  /** The submission Export would write now. */
  submissionText(): string | null;
  /** The pack the editor would export now, and whether parsePack accepts it. */
  draftText(): { text: string; ok: boolean };
}

declare global {
  interface Window {
    layerbotPackTest?: LayerbotPackTestHooks;
  }
}

export function exposePackTestHooks(app: App, session: PackSession): void {
  window.layerbotPackTest = {
    state() {
      const p = session.progress;
      const statuses: Record<string, string> = {};
      for (const c of session.pack?.challenges ?? []) statuses[c.id] = p ? progressOf(p, c.id).status : 'not started';
      const v = session.current && p ? progressOf(p, session.current.id).verdict : undefined;
      return {
        pack: session.pack?.title ?? null,
        current: session.current?.id ?? null,
        checking: session.isChecking,
        preview: session.preview,
        statuses,
        verdict: v ? { passed: v.passed, reasons: v.reasons.map((r) => ({ ...r })) } : null,
        checks: session.checks.slice(),
        restrictions: app.editRestrictions,
      };
    },
    openPackText: (text, name) => session.openText(text, name, { text, name }),
    loadController(text) {
      const r = parseController(text, 'test.controller.json');
      if (!r.ok) return false;
      app.store.openController(r.value, { name: 'test.controller.json', path: null });
      return true;
    },
    submissionText: () => session.submissionText(),
    draftText() {
      const r = checkDraft(packEditor.draft);
      return { text: r.text, ok: r.ok };
    },
  };
}
