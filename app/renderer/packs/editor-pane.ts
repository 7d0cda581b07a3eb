/**
 * The teacher's pack editor, a tab of the right-hand pane ("Pack", shown once opened from the
 * File menu): the pack's title, author and description; its challenges (add the current world
 * and controller, reorder, delete); for the selected challenge its texts, tick limit, locks per
 * layer and function, toolbox categories, criteria, hidden variant worlds and hints; the
 * problems `parsePack` finds, "Preview as student" and "Export pack…". The draft is kept in
 * local storage as pack text, so a reload loses nothing.
 */
import type { ControllerSpec } from '../../core/controller/model';
import type { FileProblem } from '../../core/formats';
import type { Pack, ToolboxCategory } from '../../core/packs/model';
import { TOOLBOX_CATEGORIES } from '../../core/packs/model';
import type { WorldSpec } from '../../core/world/world';
import { el } from '../panels/dom';
import type { ControllerPane, PaneHost } from '../panes/types';
import type { DraftChallenge, DraftCriteria, PackDraft } from './draft';
import {
  addChallenge,
  checkDraft,
  draftOfPack,
  emptyDraft,
  functionLocked,
  layerLocked,
  move,
  moveChallenge,
  packFileName,
  packText,
  readDraft,
  removeChallenge,
  setCategory,
  setCriteria,
  setFunctionLock,
  setLayerLock,
  updateChallenge,
} from './draft';

const DRAFT_KEY = 'layerbot.pack-draft.v1';
const OPEN_KEY = 'layerbot.pack-editor-open.v1';

/** What the editor needs from the app. */
export interface EditorLink {
  world(): WorldSpec;
  controller(): ControllerSpec | null;
  /** Loads a world and controller into the app (to look at or change a challenge). */
  load(world: WorldSpec, controller: ControllerSpec, id: string): void;
  openPack(): Pack | null;
  preview(text: string, name: string): void;
  save(name: string, text: string): Promise<string | null>;
  readStored(key: string): string | null;
  writeStored(key: string, text: string): boolean;
  notice(text: string, kind?: 'info' | 'error'): void;
}

export class PackEditorPane implements ControllerPane {
  readonly id = 'pack';
  readonly title = 'Pack';
  private root: HTMLElement | null = null;
  private host: PaneHost | null = null;
  private link: EditorLink | null = null;
  draft: PackDraft = emptyDraft();
  selected = 0;
  private confirmNew = false;
  private problems: readonly FileProblem[] = [];
  private checkTimer: ReturnType<typeof setTimeout> | null = null;
  private saveTimer: ReturnType<typeof setTimeout> | null = null;

  mount(element: HTMLElement, host: PaneHost): void {
    this.root = element;
    this.host = host;
    element.classList.add('pack-editor');
    this.tab()?.setAttribute('hidden', '');
    this.render();
  }

  /** Connects the editor to the app; restores the draft and whether the editor was open. */
  connect(link: EditorLink): void {
    this.link = link;
    this.draft = readDraft(link.readStored(DRAFT_KEY)) ?? emptyDraft();
    this.validate();
    if (link.readStored(OPEN_KEY) === '1') this.open();
    this.render();
  }

  /** Shows the editor's tab and brings it to the front. */
  open(): void {
    this.tab()?.removeAttribute('hidden');
    this.link?.writeStored(OPEN_KEY, '1');
    this.host?.showPane(this.id);
    this.render();
  }

  /** Hides the editor (the draft is kept). */
  closeEditor(): void {
    this.link?.writeStored(OPEN_KEY, '');
    const tab = this.tab();
    tab?.setAttribute('hidden', '');
    const first = tab?.parentElement?.querySelector<HTMLElement>('[data-pane]:not([hidden])');
    if (first?.dataset.pane) this.host?.showPane(first.dataset.pane);
  }

  private tab(): HTMLElement | null {
    return document.querySelector<HTMLElement>(`#pane-tabs [data-pane="${this.id}"]`);
  }

  // ---------- Changes ----------

  /** Replaces the draft, saves it, checks it and redraws. */
  set(draft: PackDraft, redraw = true): void {
    this.draft = draft;
    this.selected = Math.max(0, Math.min(this.selected, draft.challenges.length - 1));
    if (this.saveTimer) clearTimeout(this.saveTimer);
    this.saveTimer = setTimeout(() => this.save(), 250);
    if (this.checkTimer) clearTimeout(this.checkTimer);
    this.checkTimer = setTimeout(() => {
      this.validate();
      this.renderProblems();
    }, 250);
    if (redraw) this.render();
  }

  private save(): void {
    this.saveTimer = null;
    // The pack text is the storage format: readDraft reads it back, even when it is not valid yet.
    if (this.link && !this.link.writeStored(DRAFT_KEY, packText(this.draft))) {
      this.link.notice('The pack draft could not be kept in local storage (full or turned off); export it to keep it.', 'error');
    }
  }

  private validate(): void {
    this.checkTimer = null;
    const r = checkDraft(this.draft);
    this.problems = r.ok ? [] : r.problems;
  }

  private change(fn: (c: DraftChallenge) => DraftChallenge, redraw = true): void {
    this.set(updateChallenge(this.draft, this.selected, fn), redraw);
  }

  addCurrent(): void {
    const link = this.link;
    if (!link) return;
    const controller = link.controller();
    if (!controller) return link.notice('Open a controller first: it becomes the starter students begin from.', 'error');
    this.set(addChallenge(this.draft, link.world(), controller), false);
    this.selected = this.draft.challenges.length - 1;
    this.render();
    link.notice(`Added the challenge “${this.draft.challenges[this.selected].title}”.`);
  }

  addVariant(): void {
    const link = this.link;
    const c = this.draft.challenges[this.selected];
    if (!link || !c) return;
    const world = link.world();
    this.change((x) => setCriteria(x, (k) => ({ ...k, variants: [...k.variants, world] })));
    link.notice(`Added “${world.name}” as a hidden variant world of “${c.title}”.`);
  }

  /** Checks the draft as parsePack reads it; exports it when it has no problems. */
  async exportPack(): Promise<void> {
    const link = this.link;
    if (!link) return;
    this.validate();
    this.render();
    const r = checkDraft(this.draft);
    if (!r.ok) return link.notice(`The pack has ${r.problems.length} ${r.problems.length === 1 ? 'problem' : 'problems'}; see the Pack editor.`, 'error');
    const saved = await link.save(packFileName(this.draft), r.text);
    if (saved) link.notice(`Exported ${saved}: ${r.pack.challenges.length} challenges.`);
  }

  preview(): void {
    const link = this.link;
    if (!link) return;
    this.validate();
    this.render();
    const r = checkDraft(this.draft);
    if (!r.ok) return link.notice('Fix the pack’s problems before the preview (see the Pack editor).', 'error');
    link.preview(r.text, packFileName(this.draft));
  }

  // ---------- Drawing ----------

  render(): void {
    const root = this.root;
    if (!root) return;
    const focus = document.activeElement instanceof HTMLElement && root.contains(document.activeElement) ? document.activeElement.dataset.k : undefined;
    const scroll = root.scrollTop;
    const d = this.draft;
    const parts: HTMLElement[] = [this.header(), this.packFields(d), this.challengeList(d)];
    const c = d.challenges[this.selected];
    if (c) parts.push(this.challengeEditor(c));
    parts.push(this.footer());
    root.replaceChildren(...parts);
    root.scrollTop = scroll;
    if (focus) root.querySelector<HTMLElement>(`[data-k="${CSS.escape(focus)}"]`)?.focus();
  }

  private header(): HTMLElement {
    const h = el('div', 'pe-head');
    h.append(el('h2', undefined, 'Pack editor'));
    const newPack = el('button', 'small', this.confirmNew ? 'Discard this pack?' : 'New pack');
    newPack.dataset.k = 'new';
    newPack.id = 'pe-new';
    newPack.title = 'Start a new, empty pack (the current one is discarded)';
    newPack.addEventListener('click', () => {
      if (this.draft.challenges.length && !this.confirmNew) {
        this.confirmNew = true;
        this.render();
        setTimeout(() => {
          this.confirmNew = false;
          this.render();
        }, 4000);
        return;
      }
      this.confirmNew = false;
      this.selected = 0;
      this.set(emptyDraft());
    });
    const buttons = el('div', 'pe-head-buttons');
    buttons.append(newPack);
    const open = this.link?.openPack();
    if (open) {
      const edit = el('button', 'small', 'Edit the open pack');
      edit.title = `Load “${open.title}” into the editor (the current draft is replaced)`;
      edit.addEventListener('click', () => {
        this.selected = 0;
        this.set(draftOfPack(open));
      });
      buttons.append(edit);
    }
    const close = el('button', 'small', 'Close');
    close.title = 'Hide the pack editor (the draft is kept)';
    close.addEventListener('click', () => this.closeEditor());
    buttons.append(close);
    h.append(buttons);
    return h;
  }

  private packFields(d: PackDraft): HTMLElement {
    const s = el('section', 'pe-section');
    s.append(
      field('Title', textInput('pe-title', d.title, (v) => this.set({ ...this.draft, title: v }, false))),
      field('Author', textInput('pe-author', d.author, (v) => this.set({ ...this.draft, author: v }, false))),
      field('Description', textArea('pe-description', d.description, (v) => this.set({ ...this.draft, description: v }, false))),
    );
    return s;
  }

  private challengeList(d: PackDraft): HTMLElement {
    const s = el('section', 'pe-section');
    s.append(el('h3', undefined, `Challenges (${d.challenges.length})`));
    const ol = el('ol', 'pe-challenges');
    d.challenges.forEach((c, i) => {
      const li = el('li');
      if (i === this.selected) li.setAttribute('aria-current', 'true');
      const pick = el('button', 'pe-pick');
      pick.dataset.k = `pick-${i}`;
      pick.append(el('span', 'num', String(i + 1)), el('span', 'name', c.title || c.id), el('code', undefined, c.id));
      pick.addEventListener('click', () => {
        this.selected = i;
        this.render();
      });
      li.append(
        pick,
        iconButton('↑', `Move “${c.title}” up`, `up-${i}`, i === 0, () => {
          this.selected = i - 1;
          this.set(moveChallenge(this.draft, i, -1));
        }),
        iconButton('↓', `Move “${c.title}” down`, `down-${i}`, i === d.challenges.length - 1, () => {
          this.selected = i + 1;
          this.set(moveChallenge(this.draft, i, 1));
        }),
        iconButton('✕', `Delete “${c.title}”`, `del-${i}`, false, () => {
          if (this.selected >= i && this.selected > 0) this.selected--;
          this.set(removeChallenge(this.draft, i));
        }),
      );
      ol.appendChild(li);
    });
    if (!d.challenges.length) ol.appendChild(el('li', 'pe-empty', 'No challenges yet. Build a world and a starter controller, then add them here.'));
    const add = el('button', 'tb-button primary pe-add', 'Add the current world and controller as a challenge');
    add.id = 'pe-add-challenge';
    add.dataset.k = 'add';
    add.addEventListener('click', () => this.addCurrent());
    s.append(ol, add);
    return s;
  }

  private challengeEditor(c: DraftChallenge): HTMLElement {
    const s = el('section', 'pe-section pe-challenge');
    s.dataset.challenge = c.id;
    s.append(el('h3', undefined, `Challenge ${this.selected + 1}`));
    const ticks = numberInput('pe-max-ticks', c.maxTicks, 1, 100000, (v) => this.change((x) => ({ ...x, maxTicks: v }), false));
    s.append(
      field('Title', textInput('pe-c-title', c.title, (v) => this.change((x) => ({ ...x, title: v }), false))),
      field('Id', textInput('pe-c-id', c.id, (v) => this.change((x) => ({ ...x, id: v }), false))),
      field('Description', textArea('pe-c-description', c.description, (v) => this.change((x) => ({ ...x, description: v }), false))),
      field('Tick limit', ticks),
    );
    const world = el('div', 'pe-row pe-world');
    world.append(el('span', 'pe-note', `World “${c.world.name}”, starter “${c.starter.name}” (${c.starter.layers.length} layers)`));
    const show = el('button', 'small', 'Open in the app');
    show.title = 'Load this challenge’s world and starter into the app, to look at or change them';
    show.addEventListener('click', () => this.link?.load(c.world, c.starter, c.id));
    const useWorld = el('button', 'small', 'Use the current world');
    useWorld.addEventListener('click', () => {
      const w = this.link?.world();
      if (w) this.change((x) => ({ ...x, world: w }));
    });
    const useCtl = el('button', 'small', 'Use the current controller');
    useCtl.title = 'Make the controller open in the app this challenge’s starter';
    useCtl.addEventListener('click', () => {
      const ctl = this.link?.controller();
      if (ctl) this.change((x) => ({ ...x, starter: ctl }));
    });
    const worldButtons = el('div', 'pe-buttons');
    worldButtons.append(show, useWorld, useCtl);
    s.append(world, worldButtons);
    s.append(this.locks(c), this.toolbox(c), this.criteria(c), this.hints(c));
    return s;
  }

  private locks(c: DraftChallenge): HTMLElement {
    const box = el('fieldset', 'pe-locks');
    box.append(el('legend', undefined, 'Locked (students see, cannot change)'));
    for (const layer of c.starter.layers) {
      const whole = layerLocked(c, layer.name);
      const lk = checkbox(`lock-layer-${layer.name}`, `Layer ${layer.name}`, whole, (on) => this.change((x) => setLayerLock(x, layer.name, on)));
      lk.classList.add('pe-layer');
      box.append(lk);
      const fns = el('div', 'pe-fns');
      for (const fn of layer.functions) {
        const f = checkbox(`lock-fn-${layer.name}-${fn.name}`, fn.name, functionLocked(c, layer.name, fn.name), (on) => this.change((x) => setFunctionLock(x, layer.name, fn.name, on)));
        const input = f.querySelector('input')!;
        input.disabled = whole;
        fns.append(f);
      }
      box.append(fns);
    }
    return box;
  }

  private toolbox(c: DraftChallenge): HTMLElement {
    const box = el('fieldset', 'pe-toolbox');
    box.append(el('legend', undefined, 'Toolbox categories offered'));
    const grid = el('div', 'pe-grid');
    const offered = c.toolbox ?? TOOLBOX_CATEGORIES;
    for (const k of TOOLBOX_CATEGORIES) {
      grid.append(checkbox(`tb-${k}`, k, offered.includes(k), (on) => this.change((x) => setCategory(x, k as ToolboxCategory, on))));
    }
    const all = el('button', 'small', c.toolbox ? 'Offer all' : 'All offered');
    all.disabled = !c.toolbox;
    all.addEventListener('click', () => this.change((x) => ({ ...x, toolbox: null })));
    box.append(grid, all);
    return box;
  }

  private criteria(c: DraftChallenge): HTMLElement {
    const k = c.criteria;
    const set = (fn: (k: DraftCriteria) => DraftCriteria, redraw = true) => this.change((x) => setCriteria(x, fn), redraw);
    const box = el('fieldset', 'pe-criteria');
    box.append(el('legend', undefined, 'Success criteria (all must hold)'));
    // Reach goals
    const reach = el('div', 'pe-crit');
    reach.append(checkbox('crit-reach', 'Reach goals', k.reach.on, (on) => set((x) => ({ ...x, reach: { ...x.reach, on } }))));
    if (k.reach.on) {
      const which = select(
        'crit-reach-which',
        [
          ['plan', 'the plan'],
          ['goals', 'these goals:'],
        ],
        k.reach.goals ? 'goals' : 'plan',
        (v) => set((x) => ({ ...x, reach: { ...x.reach, goals: v === 'plan' ? null : (x.reach.goals ?? c.world.goals.map((g) => g.name)) } })),
      );
      const order = select(
        'crit-reach-order',
        [
          ['plan', 'in order'],
          ['any', 'in any order'],
        ],
        k.reach.order,
        (v) => set((x) => ({ ...x, reach: { ...x.reach, order: v === 'any' ? 'any' : 'plan' } })),
      );
      const row = el('div', 'pe-sub');
      row.append(which, order);
      reach.append(row);
      if (!k.reach.goals) reach.append(el('div', 'pe-sub pe-note', `Plan: ${c.world.plan.join(' → ') || 'empty (list the goals instead)'}`));
      if (k.reach.goals) {
        const goals = el('div', 'pe-grid pe-sub');
        for (const g of c.world.goals) {
          goals.append(
            checkbox(`crit-goal-${g.name}`, g.name, k.reach.goals.includes(g.name), (on) =>
              set((x) => ({ ...x, reach: { ...x.reach, goals: on ? [...(x.reach.goals ?? []), g.name] : (x.reach.goals ?? []).filter((n) => n !== g.name) } })),
            ),
          );
        }
        reach.append(goals);
      }
    }
    // Within N ticks
    const within = el('div', 'pe-crit pe-inline');
    within.append(
      checkbox('crit-within', 'Within', k.within.on, (on) => set((x) => ({ ...x, within: { ...x.within, on } }))),
      numberInput('crit-within-ticks', k.within.ticks, 1, 100000, (v) => set((x) => ({ ...x, within: { ...x.within, ticks: v } }), false)),
      el('span', undefined, 'ticks'),
    );
    const safe = el('div', 'pe-crit pe-inline');
    safe.append(
      checkbox('crit-no-crash', 'No crash', k.noCrash, (on) => set((x) => ({ ...x, noCrash: on }))),
      checkbox('crit-no-error', 'No error', k.noError, (on) => set((x) => ({ ...x, noError: on }))),
    );
    const blocks = el('div', 'pe-crit pe-inline');
    blocks.append(
      checkbox('crit-max-blocks', 'At most', k.maxBlocks.on, (on) => set((x) => ({ ...x, maxBlocks: { ...x.maxBlocks, on } }))),
      numberInput('crit-max-blocks-n', k.maxBlocks.blocks, 0, 100000, (v) => set((x) => ({ ...x, maxBlocks: { ...x.maxBlocks, blocks: v } }), false)),
      el('span', undefined, 'blocks in'),
      select(
        'crit-max-blocks-scope',
        [
          ['editable', 'editable functions'],
          ['all', 'all functions'],
        ],
        k.maxBlocks.scope,
        (v) => set((x) => ({ ...x, maxBlocks: { ...x.maxBlocks, scope: v === 'all' ? 'all' : 'editable' } })),
      ),
    );
    // Functions that must exist
    const fns = el('div', 'pe-crit');
    fns.append(el('div', 'pe-label', 'Functions that must exist'));
    const list = el('ul', 'pe-list');
    k.functions.forEach((f, i) => {
      const li = el('li');
      li.append(
        el('span', undefined, `“${f.function}” in layer “${f.layer}”`),
        iconButton('✕', 'Remove', `fn-del-${i}`, false, () => set((x) => ({ ...x, functions: x.functions.filter((_, j) => j !== i) }))),
      );
      list.append(li);
    });
    const layerNames = c.starter.layers.map((l) => l.name);
    const layerPick = el('input');
    layerPick.type = 'text';
    layerPick.placeholder = 'layer';
    layerPick.dataset.k = 'fn-layer';
    layerPick.id = 'crit-fn-layer';
    layerPick.setAttribute('list', 'pe-layer-names');
    const names = el('datalist');
    names.id = 'pe-layer-names';
    for (const n of layerNames) {
      const o = el('option');
      o.value = n;
      names.append(o);
    }
    const fnName = el('input');
    fnName.type = 'text';
    fnName.placeholder = 'function';
    fnName.dataset.k = 'fn-name';
    fnName.id = 'crit-fn-name';
    const addFn = el('button', 'small', 'Add');
    addFn.id = 'crit-fn-add';
    addFn.addEventListener('click', () => {
      const layer = layerPick.value.trim();
      const fn = fnName.value.trim();
      if (!layer || !fn) return this.link?.notice('Name the layer and the function.', 'error');
      set((x) => ({ ...x, functions: [...x.functions, { layer, function: fn }] }));
    });
    const addRow = el('div', 'pe-inline');
    addRow.append(layerPick, names, fnName, addFn);
    fns.append(list, addRow);
    // Variants
    const variants = el('div', 'pe-crit');
    variants.append(el('div', 'pe-label', 'Hidden variant worlds (must pass there too)'));
    const vl = el('ul', 'pe-list');
    k.variants.forEach((w, i) => {
      const li = el('li');
      li.append(
        el('span', undefined, `${i + 1}. ${w.name}`),
        iconButton('✕', `Remove the variant “${w.name}”`, `var-del-${i}`, false, () => set((x) => ({ ...x, variants: x.variants.filter((_, j) => j !== i) }))),
      );
      vl.append(li);
    });
    const addVar = el('button', 'small', 'Add the current world as a hidden variant');
    addVar.id = 'crit-add-variant';
    addVar.addEventListener('click', () => this.addVariant());
    variants.append(vl, addVar);
    box.append(reach, within, safe, blocks, fns, variants);
    return box;
  }

  private hints(c: DraftChallenge): HTMLElement {
    const box = el('fieldset', 'pe-hints');
    box.append(el('legend', undefined, 'Hints (revealed one at a time)'));
    const ol = el('ol', 'pe-hint-list');
    c.hints.forEach((h, i) => {
      const li = el('li');
      const ta = textArea(`hint-${i}`, h, (v) => this.change((x) => ({ ...x, hints: x.hints.map((y, j) => (j === i ? v : y)) }), false));
      ta.rows = 2;
      li.append(
        ta,
        iconButton('↑', 'Move up', `hint-up-${i}`, i === 0, () => this.change((x) => ({ ...x, hints: move(x.hints, i, -1) }))),
        iconButton('↓', 'Move down', `hint-down-${i}`, i === c.hints.length - 1, () => this.change((x) => ({ ...x, hints: move(x.hints, i, 1) }))),
        iconButton('✕', 'Remove the hint', `hint-del-${i}`, false, () => this.change((x) => ({ ...x, hints: x.hints.filter((_, j) => j !== i) }))),
      );
      ol.append(li);
    });
    const add = el('button', 'small', 'Add a hint');
    add.id = 'pe-add-hint';
    add.addEventListener('click', () => {
      this.change((x) => ({ ...x, hints: [...x.hints, ''] }));
      this.root?.querySelector<HTMLElement>(`[data-k="hint-${c.hints.length}"]`)?.focus();
    });
    box.append(ol, add);
    return box;
  }

  private footer(): HTMLElement {
    const f = el('section', 'pe-section pe-footer');
    const problems = el('div', 'pe-problems');
    problems.id = 'pe-problems';
    f.append(problems);
    const buttons = el('div', 'pe-buttons');
    const preview = el('button', 'small', 'Preview as student');
    preview.id = 'pe-preview';
    preview.addEventListener('click', () => this.preview());
    const exp = el('button', 'tb-button primary', 'Export pack…');
    exp.id = 'pe-export';
    exp.addEventListener('click', () => void this.exportPack());
    buttons.append(preview, exp);
    f.append(buttons);
    queueMicrotask(() => this.renderProblems());
    return f;
  }

  private renderProblems(): void {
    const box = this.root?.querySelector('#pe-problems');
    if (!box) return;
    if (!this.problems.length) {
      box.className = 'pe-problems ok';
      box.replaceChildren(el('span', undefined, `✓ Ready to export: ${this.draft.challenges.length} ${this.draft.challenges.length === 1 ? 'challenge' : 'challenges'}.`));
      return;
    }
    box.className = 'pe-problems err';
    const ul = el('ul');
    for (const p of this.problems.slice(0, 8)) {
      const li = el('li');
      li.append(el('span', undefined, p.message), el('code', undefined, p.path));
      ul.append(li);
    }
    if (this.problems.length > 8) ul.append(el('li', undefined, `and ${this.problems.length - 8} more`));
    box.replaceChildren(el('b', undefined, `${this.problems.length} ${this.problems.length === 1 ? 'problem' : 'problems'} to fix before export`), ul);
  }
}

// ---------- Small form builders ----------

function field(label: string, input: HTMLElement): HTMLElement {
  const l = el('label', 'pe-field');
  l.append(el('span', undefined, label), input);
  return l;
}

function textInput(key: string, value: string, onInput: (v: string) => void): HTMLInputElement {
  const i = el('input');
  i.type = 'text';
  i.value = value;
  i.dataset.k = key;
  i.id = key;
  i.addEventListener('input', () => onInput(i.value));
  return i;
}

function textArea(key: string, value: string, onInput: (v: string) => void): HTMLTextAreaElement {
  const t = el('textarea');
  t.value = value;
  t.rows = 3;
  t.dataset.k = key;
  t.id = key;
  t.addEventListener('input', () => onInput(t.value));
  return t;
}

function numberInput(key: string, value: number, min: number, max: number, onInput: (v: number) => void): HTMLInputElement {
  const i = el('input');
  i.type = 'number';
  i.min = String(min);
  i.max = String(max);
  i.step = '1';
  i.value = String(value);
  i.dataset.k = key;
  i.id = key;
  i.addEventListener('input', () => {
    const v = Number(i.value);
    if (Number.isInteger(v)) onInput(v);
  });
  return i;
}

function checkbox(key: string, label: string, checked: boolean, onChange: (on: boolean) => void): HTMLLabelElement {
  const l = el('label', 'check');
  const i = el('input');
  i.type = 'checkbox';
  i.checked = checked;
  i.dataset.k = key;
  i.id = `pe-${key.replace(/[^A-Za-z0-9-]/g, '_')}`;
  i.addEventListener('change', () => onChange(i.checked));
  l.append(i, el('span', undefined, label));
  return l;
}

function select(key: string, options: readonly (readonly [string, string])[], value: string, onChange: (v: string) => void): HTMLSelectElement {
  const s = el('select');
  s.dataset.k = key;
  s.id = key;
  for (const [v, text] of options) {
    const o = el('option', undefined, text);
    o.value = v;
    s.append(o);
  }
  s.value = value;
  s.addEventListener('change', () => onChange(s.value));
  return s;
}

function iconButton(text: string, title: string, key: string, disabled: boolean, onClick: () => void): HTMLButtonElement {
  const b = el('button', 'pack-icon-btn', text);
  b.title = title;
  b.setAttribute('aria-label', title);
  b.dataset.k = key;
  b.disabled = disabled;
  b.addEventListener('click', onClick);
  return b;
}

/** The one pack editor of the page (app.ts mounts it in the right-hand pane). */
export const packEditor = new PackEditorPane();

export function packPanes(): ControllerPane[] {
  return [packEditor];
}
