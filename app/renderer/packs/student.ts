/**
 * What a student sees of a pack: the "Challenges" card at the top of the left column (the pack,
 * its challenges with their progress, Check, the student's name, Export submission) and the
 * "Challenge" tab of the dock (the description, hints one at a time, and the verdict, every
 * reason with ✓ or ✗). The view only draws and reports clicks; `PackSession` decides.
 */
import type { FileProblem } from '../../core/formats';
import type { Challenge, Pack } from '../../core/packs/model';
import { el } from '../panels/dom';
import type { ChallengeStatus, PackProgress } from './progress';
import { progressOf, tally } from './progress';
import { headline, verdictGroups } from './verdict';

export interface StudentActions {
  select(id: string): void;
  check(): void;
  hint(): void;
  resetToStarter(): void;
  exportSubmission(): void;
  setStudent(name: string): void;
  close(): void;
  backToEditor(): void;
  dismissProblems(): void;
}

export interface StudentState {
  readonly pack: Pack | null;
  readonly progress: PackProgress | null;
  readonly current: Challenge | null;
  readonly checking: boolean;
  /** Opened from the pack editor's "Preview as student". */
  readonly preview: boolean;
  /** Problems of the last pack that could not be opened. */
  readonly problems: { readonly file: string; readonly list: readonly FileProblem[] } | null;
}

const ICON: Record<ChallengeStatus, string> = { 'not started': '○', attempted: '◐', passed: '✓' };

export class StudentView {
  readonly card = el('section', 'card pack-card');
  readonly tab = el('button');
  readonly panel = el('div', 'dock-panel challenge-panel');
  private readonly nameInput = el('input');

  constructor(private readonly actions: StudentActions) {
    this.card.id = 'pack-card';
    this.card.setAttribute('aria-label', 'Challenges');
    this.card.hidden = true;
    this.tab.setAttribute('role', 'tab');
    this.tab.dataset.dock = 'challenge';
    this.tab.setAttribute('aria-selected', 'false');
    this.tab.id = 'challenge-tab';
    this.tab.textContent = 'Challenge';
    this.tab.hidden = true;
    this.panel.dataset.dockPanel = 'challenge';
    this.panel.id = 'challenge-panel';
    this.panel.hidden = true;
    this.nameInput.type = 'text';
    this.nameInput.id = 'pack-student';
    this.nameInput.placeholder = 'Your name';
    this.nameInput.autocomplete = 'name';
    this.nameInput.addEventListener('change', () => actions.setStudent(this.nameInput.value));
  }

  /** Puts the card, the tab and the panel into the page (before the app binds the dock's tabs). */
  attach(sidebar: HTMLElement, dock: HTMLElement): void {
    sidebar.prepend(this.card);
    const tabs = dock.querySelector('.tabs');
    tabs?.insertBefore(this.tab, tabs.querySelector('.dock-info'));
    dock.querySelector('.dock-body')?.appendChild(this.panel);
  }

  render(s: StudentState): void {
    this.renderCard(s);
    this.renderPanel(s);
  }

  private renderCard(s: StudentState): void {
    const { pack, progress } = s;
    this.card.hidden = !pack && !s.problems;
    this.tab.hidden = !pack;
    const head = el('h2', undefined, s.preview ? 'Preview as student' : 'Challenges');
    if (pack) {
      const close = el('button', 'pack-icon-btn', '×');
      close.title = s.preview ? 'End the preview' : 'Close the pack';
      close.setAttribute('aria-label', close.title);
      close.id = 'pack-close';
      close.addEventListener('click', () => (s.preview ? this.actions.backToEditor() : this.actions.close()));
      head.appendChild(close);
    }
    const parts: HTMLElement[] = [head];
    if (s.problems) parts.push(this.problemBox(s.problems));
    if (pack && progress) {
      const t = tally(pack, progress);
      const title = el('div', 'pack-title', pack.title);
      title.title = pack.description;
      const bar = el('div', 'pack-progress');
      const track = el('div', 'track');
      const fill = el('i');
      fill.style.width = `${(100 * t.passed) / Math.max(1, t.total)}%`;
      track.appendChild(fill);
      bar.append(track, el('span', undefined, `${t.passed} of ${t.total} passed`));
      const list = el('ol', 'challenge-list');
      pack.challenges.forEach((c, i) => {
        const status = progressOf(progress, c.id).status;
        const b = el('button');
        b.dataset.challenge = c.id;
        b.dataset.status = status;
        b.title = `${c.title}: ${status}`;
        if (s.current?.id === c.id) b.setAttribute('aria-current', 'true');
        const icon = el('span', `st st-${status.replace(' ', '-')}`, ICON[status]);
        icon.setAttribute('aria-label', status);
        b.append(el('span', 'num', String(i + 1)), el('span', 'name', c.title), icon);
        b.addEventListener('click', () => this.actions.select(c.id));
        const li = el('li');
        li.appendChild(b);
        list.appendChild(li);
      });
      const check = el('button', 'tb-button primary pack-check', s.checking ? 'Checking…' : 'Check');
      check.id = 'pack-check';
      check.disabled = !s.current || s.checking;
      check.title = 'Grade the controller on this challenge: every criterion, also on hidden worlds';
      check.addEventListener('click', () => this.actions.check());
      const verdictLine = el('div', 'pack-verdict-line');
      verdictLine.id = 'pack-verdict-line';
      const v = s.current ? progressOf(progress, s.current.id).verdict : undefined;
      if (s.checking) verdictLine.append(el('span', 'pill run', 'Checking…'));
      else if (v) {
        const pill = el('span', `pill ${v.passed ? 'ok' : 'err'}`, v.passed ? 'Passed' : 'Not passed yet');
        const more = el('button', 'linkish', 'Details');
        more.addEventListener('click', () => this.tab.click());
        verdictLine.append(pill, more);
      }
      const name = el('label', 'pack-name');
      name.append(el('span', undefined, 'Name'), this.nameInput);
      if (document.activeElement !== this.nameInput) this.nameInput.value = progress.student;
      const exp = el('button', 'small', 'Export submission…');
      exp.id = 'pack-export';
      exp.title = 'Save your work on every challenge as one file for your teacher';
      exp.addEventListener('click', () => this.actions.exportSubmission());
      const row = el('div', 'row pack-actions');
      row.append(check, verdictLine);
      const row2 = el('div', 'row pack-submit');
      row2.append(name, exp);
      parts.push(title, bar, list, row);
      if (!s.preview) parts.push(row2);
      if (s.preview) {
        const back = el('button', 'small', 'Back to the pack editor');
        back.id = 'pack-back-to-editor';
        back.addEventListener('click', () => this.actions.backToEditor());
        const bar2 = el('div', 'pack-preview-note');
        bar2.append(el('span', undefined, 'Progress in a preview is not kept.'), back);
        parts.push(bar2);
      }
    }
    const focused = document.activeElement === this.nameInput;
    this.card.replaceChildren(...parts);
    if (focused) this.nameInput.focus();
  }

  private problemBox(p: { file: string; list: readonly FileProblem[] }): HTMLElement {
    const box = el('div', 'pack-problems');
    box.id = 'pack-problems';
    box.setAttribute('role', 'alert');
    const dismiss = el('button', 'pack-icon-btn', '×');
    dismiss.title = 'Dismiss';
    dismiss.setAttribute('aria-label', 'Dismiss');
    dismiss.addEventListener('click', () => this.actions.dismissProblems());
    const head = el('div', 'pack-problems-head');
    head.append(el('b', undefined, `${p.file} could not be opened as a pack`), dismiss);
    box.append(head);
    const ul = el('ul');
    const shown = p.list.slice(0, 6);
    for (const q of shown) {
      const li = el('li');
      li.append(el('span', 'msg', q.message), el('code', undefined, `${q.path}${q.line !== undefined ? ` (line ${q.line})` : ''}`));
      ul.appendChild(li);
    }
    if (p.list.length > shown.length) ul.appendChild(el('li', 'more', `and ${p.list.length - shown.length} more`));
    box.appendChild(ul);
    return box;
  }

  private renderPanel(s: StudentState): void {
    const c = s.current;
    if (!c || !s.progress) {
      this.panel.replaceChildren(el('div', 'empty-state', 'Choose a challenge in the Challenges list.'));
      return;
    }
    const p = progressOf(s.progress, c.id);
    const info = el('div', 'challenge-info');
    const h = el('h3', undefined, c.title);
    h.appendChild(el('span', `pill ${p.status === 'passed' ? 'ok' : p.status === 'attempted' ? 'warn' : ''}`, p.status));
    info.append(h, el('p', 'challenge-desc', c.description));
    const hints = el('div', 'challenge-hints');
    if (c.hints.length) {
      const ol = el('ol');
      c.hints.slice(0, p.hints).forEach((text) => ol.appendChild(el('li', undefined, text)));
      if (p.hints) hints.appendChild(ol);
      const more = el('button', 'small', p.hints >= c.hints.length ? 'No more hints' : `Show hint ${p.hints + 1} of ${c.hints.length}`);
      more.id = 'pack-hint';
      more.disabled = p.hints >= c.hints.length;
      more.addEventListener('click', () => this.actions.hint());
      hints.appendChild(more);
    }
    const reset = el('button', 'small', 'Start again from the starter');
    reset.id = 'pack-reset-work';
    reset.title = 'Replace your controller for this challenge with the starter controller';
    reset.disabled = !p.work;
    reset.addEventListener('click', () => this.actions.resetToStarter());
    const tools = el('div', 'row');
    tools.append(hints, reset);
    info.append(tools);

    const verdict = el('div', 'challenge-verdict');
    verdict.id = 'challenge-verdict';
    verdict.setAttribute('aria-live', 'polite');
    if (s.checking) {
      verdict.append(el('div', 'verdict-head checking', 'Checking on the challenge world and its hidden variants…'));
    } else if (!p.verdict) {
      verdict.append(el('div', 'verdict-head none', 'Not checked yet. Run the robot, or press Check.'));
    } else {
      const v = p.verdict;
      verdict.dataset.passed = String(v.passed);
      const head = el('div', `verdict-head ${v.passed ? 'ok' : 'err'}`, headline(v));
      if (v.ms !== undefined) head.appendChild(el('span', 'ms', `checked in ${(v.ms / 1000).toFixed(1)} s`));
      verdict.append(head);
      for (const g of verdictGroups(v)) {
        const group = el('div', 'verdict-group');
        if (g.world !== null) group.append(el('div', 'verdict-world', `On ${g.world}`));
        for (const r of g.reasons) {
          const row = el('div', `reason ${r.passed ? 'ok' : 'err'}`);
          row.dataset.passed = String(r.passed);
          const mark = el('span', 'mark', r.passed ? '✓' : '✗');
          mark.setAttribute('aria-label', r.passed ? 'passed' : 'failed');
          row.append(mark, el('span', 'crit', r.criterion), el('span', 'detail', r.detail));
          group.appendChild(row);
        }
        verdict.appendChild(group);
      }
    }
    this.panel.replaceChildren(info, verdict);
  }
}
