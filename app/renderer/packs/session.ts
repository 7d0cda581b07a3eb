/**
 * Challenge packs in the app, the student's side: the open pack, the open challenge (its world
 * and the student's work loaded into the app, its locks and toolbox applied), Check in the
 * grading Worker (also after every run), hints, progress saved per pack and restored, and the
 * submission export. Pack files that cannot be read are reported by challenge and field; the
 * app keeps working.
 */
import type { OpenedFile } from '../../main/api';
import type { ControllerSpec } from '../../core/controller/model';
import type { FileProblem } from '../../core/formats';
import type { Challenge, Pack } from '../../core/packs/model';
import { parsePack } from '../../core/packs/parse-pack';
import { serializeSubmission } from '../../core/packs/parse-submission';
import type { App } from '../app/app';
import type { Platform } from '../files/platform';
import { BUNDLED_PACKS } from './bundled';
import { GradeClient } from './grade-client';
import type { PackProgress } from './progress';
import {
  emptyProgress,
  forgetWork,
  progressKey,
  progressOf,
  readProgress,
  recordVerdict,
  recordWork,
  revealHint,
  setCurrent,
  setStudent,
  submissionFileName,
  submissionOf,
  workFor,
  writeProgress,
} from './progress';
import { StudentView } from './student';

/** Which pack is open, so a reload reopens it. */
const OPEN_KEY = 'layerbot.pack-open.v1';

type PackSource = { readonly bundled: string; readonly name: string } | { readonly text: string; readonly name: string };

export class PackSession {
  pack: Pack | null = null;
  progress: PackProgress | null = null;
  current: Challenge | null = null;
  preview = false;
  private source: PackSource | null = null;
  private problems: { file: string; list: readonly FileProblem[] } | null = null;
  private readonly grader = new GradeClient();
  private checking = false;
  private wasRunning = false;
  private saveTimer: ReturnType<typeof setTimeout> | null = null;
  private switching = false;
  readonly view: StudentView;
  /** Called by "Back to the pack editor" in a preview. */
  onBackToEditor: (() => void) | null = null;
  /** Timings of the Checks made, for the tests and for measuring. */
  readonly checks: { challenge: string; ms: number; workerMs?: number; passed: boolean }[] = [];

  constructor(
    private readonly app: App,
    private readonly platform: Platform,
  ) {
    this.view = new StudentView({
      select: (id) => this.openChallenge(id),
      check: () => void this.check(),
      hint: () => this.hint(),
      resetToStarter: () => this.resetToStarter(),
      exportSubmission: () => void this.exportSubmission(),
      setStudent: (name) => this.update(setStudent(this.need(), name), true),
      close: () => this.close(),
      backToEditor: () => this.onBackToEditor?.(),
      dismissProblems: () => this.dismissProblems(),
    });
    app.store.onController.on(() => this.controllerChanged());
    app.engine.onStatus.on((s) => {
      // A run ended (the robot crashed or finished, an error, or Stop): check the work.
      if (this.wasRunning && !s.running && this.current) void this.check();
      this.wasRunning = s.running;
    });
    window.addEventListener('pagehide', () => this.flush());
  }

  /** Reopens the pack (and challenge) open before the page was reloaded. */
  async restore(): Promise<void> {
    const text = this.platform.readStored(OPEN_KEY);
    if (!text) return;
    try {
      const open = JSON.parse(text) as { source?: PackSource; challenge?: string };
      if (!open.source) return;
      const packText = 'bundled' in open.source ? await bundledText(open.source.bundled) : open.source.text;
      if (packText === null) return;
      this.openText(packText, open.source.name, open.source, false);
    } catch {
      // A broken record: start without a pack.
    }
  }

  /** Opens a bundled pack by file name. */
  async openBundled(file: string): Promise<boolean> {
    const text = await bundledText(file);
    if (text === null) return this.fail(file, [{ file, path: '$', message: 'this pack is not part of this build' }]);
    return this.openText(text, file, { bundled: file, name: file });
  }

  /** Opens a pack file the user chose. */
  async openFile(): Promise<void> {
    const file = await this.platform.openFile('any');
    if (file) this.openOpened(file);
  }

  /** Opens a pack from an opened file (File › Open… hands pack files here). */
  openOpened(file: OpenedFile): boolean {
    return this.openText(file.text, file.name, { text: file.text, name: file.name });
  }

  /**
   * Opens pack text. A pack that cannot be read leaves what was open as it was, and shows every
   * problem by challenge and field.
   */
  openText(text: string, name: string, source: PackSource | null, announce = true, preview = false): boolean {
    const parsed = parsePack(text, name);
    if (!parsed.ok) return this.fail(name, parsed.problems);
    this.flush();
    this.grader.cancel();
    this.checking = false;
    this.problems = null;
    this.pack = parsed.value;
    this.preview = preview;
    this.source = source;
    this.progress = preview ? emptyProgress(this.pack.title) : readProgress(this.platform.readStored(progressKey(this.pack.title)), this.pack.title);
    if (!preview && source) this.platform.writeStored(OPEN_KEY, JSON.stringify({ source: keptSource(source) }));
    const first = this.pack.challenges.find((c) => c.id === this.progress?.current) ?? this.pack.challenges[0];
    this.current = null;
    this.openChallenge(first.id);
    if (announce) this.app.store.notice(`Opened the pack “${this.pack.title}”: ${this.pack.challenges.length} challenges.`);
    return true;
  }

  /** Opens a challenge: its world, the student's work (or the starter), its locks and toolbox. */
  openChallenge(id: string): void {
    const pack = this.pack;
    const c = pack?.challenges.find((x) => x.id === id);
    if (!pack || !c || !this.progress) return;
    this.flush();
    if (this.checking) {
      this.grader.cancel();
      this.checking = false;
    }
    this.current = c;
    this.progress = setCurrent(this.progress, id);
    this.switching = true;
    try {
      this.app.setRestrictions({ locked: c.locked, ...(c.toolbox ? { toolbox: c.toolbox } : {}) });
      this.app.store.setMode('solve');
      this.app.store.openWorld(c.world, { name: `${c.id}.world.json`, path: null });
      this.app.store.openController(workFor(this.progress, id, c.starter), { name: `${c.id}.controller.json`, path: null });
    } finally {
      this.switching = false;
    }
    this.saveSoon();
    this.render();
    this.view.tab.click();
  }

  /** Grades the controller on the open challenge, in the grading Worker. */
  async check(): Promise<void> {
    const c = this.current;
    const controller = this.app.store.controller;
    if (!c || !this.progress) return;
    if (!controller) return this.app.store.notice('There is no controller to check.', 'error');
    this.checking = true;
    this.render();
    const result = await this.grader.check(c, controller);
    if (!result) return; // replaced by a newer Check, or the challenge changed
    this.checking = false;
    if (this.current?.id !== c.id) return this.render();
    const v = result.verdict;
    this.checks.push({ challenge: c.id, ms: result.ms, passed: v.passed });
    this.update(recordVerdict(this.progress, c.id, v, result.ms), true);
    this.app.store.notice(v.passed ? `“${c.title}” passed.` : `“${c.title}”: not passed yet. See the Challenge tab.`, v.passed ? 'info' : 'error');
    this.view.tab.click();
  }

  get isChecking(): boolean {
    return this.checking;
  }

  hint(): void {
    const c = this.current;
    if (!c || !this.progress) return;
    this.update(revealHint(this.progress, c.id, c.hints.length), true);
  }

  resetToStarter(): void {
    const c = this.current;
    if (!c || !this.progress) return;
    this.update(forgetWork(this.progress, c.id), true);
    this.switching = true;
    try {
      this.app.store.openController(c.starter, { name: `${c.id}.controller.json`, path: null });
    } finally {
      this.switching = false;
    }
    this.app.store.notice('Back to the starter controller.');
  }

  async exportSubmission(): Promise<void> {
    const pack = this.pack;
    if (!pack || !this.progress) return;
    if (this.preview) return this.app.store.notice('This is a preview: export the pack, not a submission.', 'error');
    this.flush();
    const name = (document.getElementById('pack-student') as HTMLInputElement | null)?.value ?? this.progress.student;
    if (name !== this.progress.student) this.update(setStudent(this.progress, name), true);
    if (!this.progress.student.trim()) {
      document.getElementById('pack-student')?.focus();
      return this.app.store.notice('Type your name first, so your teacher knows whose work it is.', 'error');
    }
    const submission = submissionOf(pack, this.progress);
    const text = serializeSubmission(submission);
    try {
      const saved = await this.platform.saveFile('any', null, submissionFileName(pack, this.progress), text);
      if (saved) this.app.store.notice(`${this.platform.desktop ? 'Saved' : 'Downloaded'} ${saved.name}: ${Object.keys(submission.controllers).length} challenges.`);
    } catch (e) {
      this.app.store.notice(`Could not save the submission: ${e instanceof Error ? e.message : String(e)}`, 'error');
    }
  }

  /** Closes the pack: nothing is restricted any more; the world and controller stay open. */
  close(): void {
    this.flush();
    this.grader.cancel();
    this.checking = false;
    this.pack = null;
    this.progress = null;
    this.current = null;
    this.source = null;
    this.preview = false;
    this.problems = null;
    this.platform.writeStored(OPEN_KEY, '');
    this.app.setRestrictions(null);
    this.render();
    this.app.store.notice('Closed the pack.');
  }

  /** The submission the student would export now (for the tests). */
  submissionText(): string | null {
    this.flush();
    return this.pack && this.progress ? serializeSubmission(submissionOf(this.pack, this.progress)) : null;
  }

  render(): void {
    this.view.render({ pack: this.pack, progress: this.progress, current: this.current, checking: this.checking, preview: this.preview, problems: this.problems });
  }

  dismissProblems(): void {
    this.problems = null;
    this.render();
  }

  private fail(file: string, list: readonly FileProblem[]): false {
    this.problems = { file, list };
    this.render();
    const first = list[0];
    this.app.store.notice(`${file} could not be opened as a pack: ${first ? first.message : 'unknown problem'}`, 'error');
    return false;
  }

  private controllerChanged(): void {
    const c = this.current;
    if (!c || !this.progress || this.switching) return;
    const before = progressOf(this.progress, c.id).status;
    this.progress = recordWork(this.progress, c.id, this.app.store.controller, c.starter);
    this.saveSoon();
    if (progressOf(this.progress, c.id).status !== before) this.render();
  }

  private update(p: PackProgress, saveNow: boolean): void {
    this.progress = p;
    if (saveNow) this.flush(true);
    else this.saveSoon();
    this.render();
  }

  private need(): PackProgress {
    if (!this.progress) throw new Error('no pack is open');
    return this.progress;
  }

  private saveSoon(): void {
    if (this.saveTimer) clearTimeout(this.saveTimer);
    this.saveTimer = setTimeout(() => this.flush(true), 300);
  }

  /** Writes the progress now (when a save is pending, or `force`). */
  flush(force = false): void {
    const pending = this.saveTimer !== null;
    if (this.saveTimer) clearTimeout(this.saveTimer);
    this.saveTimer = null;
    if ((!pending && !force) || !this.progress || this.preview) return;
    if (!this.platform.writeStored(progressKey(this.progress.pack), writeProgress(this.progress))) {
      this.app.store.notice('Your progress could not be saved: the browser’s storage is full or turned off.', 'error');
    }
  }

  /** The student's controller for the open challenge, as the app holds it. */
  controller(): ControllerSpec | null {
    return this.app.store.controller;
  }
}

async function bundledText(file: string): Promise<string | null> {
  const entry = BUNDLED_PACKS.find((b) => b.file === file);
  return entry ? entry.load() : null;
}

/** What is kept to reopen a pack: bundled packs by name, others by their text. */
function keptSource(s: PackSource): PackSource {
  return 'bundled' in s ? { bundled: s.bundled, name: s.name } : { text: s.text, name: s.name };
}
