/**
 * The "Debugger" tab of the bottom dock: replays one function at the selected tick in
 * JS-Interpreter, block by block (the Stepper, app/core/sandbox/stepper.ts), showing the code with
 * the current block's line, the variables and inputs, the printed lines, and the result compared
 * with what the run recorded. Each step highlights the block in the Blocks pane.
 *
 * Started from the editor or the diagram (`app.stepIntoHandler`), from a function's rows in the
 * arc table, or from this panel's function picker.
 *
 * It runs on the page's thread: it is one function, interactive and small; the inputs are already
 * here (the arc rows), so nothing large is copied to another worker; and a long step runs in
 * slices between which the page draws and Close works. The step budget bounds every step.
 */
import './debugger.css';
import type { Local, StepKind, StepView } from '../../core/sandbox/stepper';
import { Stepper } from '../../core/sandbox/stepper';
import { formatValue, sameValue } from '../../core/values';
import type { App } from '../app/app';
import { byId, el, isTyping } from '../panels/dom';
import { shortValue } from '../panels/format';
import type { Recorded, ReplayPlan } from './replay';
import { planReplay, recordedOutput } from './replay';

/** Interpreter steps per slice: about 10-30 ms, so the page keeps drawing during a long step. */
const SLICE_STEPS = 150_000;

interface Replay {
  readonly plan: ReplayPlan;
  readonly stepper: Stepper;
  view: StepView;
  /** The variables where it last paused, still shown once the call has ended. */
  lastFrames: StepView['frames'];
}

export function installDebugger(app: App): Debugger {
  return new Debugger(app, byId('debugger-panel'));
}

export class Debugger {
  private replay: Replay | null = null;
  /** Bumped whenever a replay opens, closes or restarts: stale slices and answers stop. */
  private generation = 0;
  private readonly picker = el('select', 'dbg-picker');
  private readonly startButton = el('button', 'small dbg-start', 'Step into');
  private readonly startGroup = el('div', 'dbg-start-group');
  private readonly title = el('div', 'dbg-title');
  private readonly controls = el('div', 'dbg-controls');
  private readonly body = el('div', 'dbg-body');
  private readonly buttons: Record<'block' | 'into' | 'out' | 'end' | 'restart' | 'close', HTMLButtonElement>;
  private codeLines: HTMLElement[] = [];
  private code = el('ol', 'dbg-code');
  private readonly vars = el('div', 'dbg-vars');
  private readonly side = el('div', 'dbg-side');

  constructor(
    private readonly app: App,
    private readonly root: HTMLElement,
  ) {
    root.classList.add('dbg');
    this.picker.setAttribute('aria-label', 'Function to step into');
    this.startButton.title = 'Replay this function at the selected tick, block by block';
    this.startButton.addEventListener('click', () => {
      const [layer, fn] = this.picker.value.split('\u0000');
      if (fn) void this.open(layer, fn, app.store.selectedTick);
    });
    const button = (label: string, key: string, title: string, act: () => void): HTMLButtonElement => {
      const b = el('button', 'small', label);
      b.title = `${title} (${key})`;
      b.addEventListener('click', act);
      this.controls.appendChild(b);
      return b;
    };
    this.buttons = {
      block: button('Step', 'F10', 'Run this block; stop at the next one in this function', () => this.act('block')),
      into: button('Step into', 'F11', 'Stop at the very next block, inside a helper procedure if this block calls one', () => this.act('into')),
      out: button('Step out', 'Shift+F11', 'Finish this helper procedure (or the function)', () => this.act('out')),
      end: button('Continue', 'F8', 'Run to the end', () => this.act('end')),
      restart: button('Restart', 'Shift+F8', 'Start the replay again', () => this.restart()),
      close: button('Close', 'Esc', 'Close the replay', () => this.close()),
    };
    this.buttons.block.dataset.step = 'block';
    this.buttons.into.dataset.step = 'into';
    this.buttons.out.dataset.step = 'out';
    this.buttons.end.dataset.step = 'end';
    const bar = el('div', 'dbg-bar');
    this.startGroup.append(this.picker, this.startButton);
    bar.append(this.startGroup, this.title, this.controls);
    root.replaceChildren(bar, this.body);

    app.stepIntoHandler = (layer, fn) => void this.open(layer, fn, app.store.selectedTick);
    app.engine.onLoaded.on(() => {
      this.fillPicker();
      if (this.replay) this.close('The run was reset: the replay closed.');
    });
    app.store.onSelect.on(() => this.renderIdle());
    byId('arc-panel').addEventListener('click', (e) => this.arcClick(e));
    document.addEventListener('keydown', (e) => this.key(e));
    this.fillPicker();
    this.render();
  }

  /** Replays `fn` (of `layer`) at `tick`. */
  async open(layer: string, fn: string, tick: number): Promise<void> {
    const app = this.app;
    this.showTab();
    const gen = this.dispose();
    const spec = app.store.controller;
    const frames = app.engine.frames;
    if (!spec || !app.engine.state.hasController) return this.fail('Open a controller and run it first.');
    if (tick < 1 || tick >= frames.length) return this.fail(tick < 1 ? 'Tick 0 is the start: no function has run yet. Step once, select a tick, then step into a function.' : `Tick ${tick} has not been computed yet.`);
    this.message('Preparing the replay…', `${fn} at tick ${tick}`);
    try {
      const rows = await app.engine.arcs(tick);
      const recorded = await recordedOutput(fn, tick, rows, frames[tick].error, tick + 1 < frames.length ? () => app.engine.arcs(tick + 1) : null);
      if (gen !== this.generation) return;
      const plan = planReplay(spec, layer, fn, tick, rows, recorded);
      const stepper = new Stepper(plan.options);
      this.replay = { plan, stepper, view: stepper.current(), lastFrames: [] };
      this.buildCode();
      this.select(plan.layer, plan.function);
      // Stop at the first block (a text function, with no blocks, runs to its end).
      this.act('into');
    } catch (e) {
      if (gen === this.generation) this.fail(e instanceof Error ? e.message : String(e));
    }
  }

  /** Carries out one step, in slices. */
  act(kind: StepKind): void {
    const r = this.replay;
    if (!r || r.view.done) return;
    const gen = ++this.generation;
    r.stepper.start(kind);
    const slice = (): void => {
      if (gen !== this.generation) return;
      r.view = r.stepper.run(SLICE_STEPS);
      if (!r.view.done) r.lastFrames = r.view.frames;
      this.render();
      if (r.view.busy) setTimeout(slice, 0);
    };
    slice();
  }

  restart(): void {
    const r = this.replay;
    if (!r) return;
    this.generation++;
    r.view = r.stepper.restart();
    r.lastFrames = [];
    this.act('into');
  }

  /** Closes the replay and clears the block highlight. */
  close(note?: string): void {
    const had = this.replay !== null;
    this.dispose();
    if (had) this.app.paneArea.highlightStep(null);
    this.render();
    if (note) this.app.store.notice(note);
  }

  /** The view shown now (for tests and the keys). */
  get current(): StepView | null {
    return this.replay?.view ?? null;
  }

  private dispose(): number {
    this.replay?.stepper.dispose();
    this.replay = null;
    this.codeLines = [];
    return ++this.generation;
  }

  private showTab(): void {
    document.querySelector<HTMLButtonElement>('#dock [data-dock="debugger"]')?.click();
  }

  private fillPicker(): void {
    const before = this.picker.value;
    const options = this.app.engine.functions.map((f) => {
      const o = el('option', undefined, `${f.name}  (${f.layer})`);
      o.value = `${f.layer}\u0000${f.name}`;
      return o;
    });
    this.picker.replaceChildren(...options);
    if (options.some((o) => o.value === before)) this.picker.value = before;
    this.renderIdle();
  }

  private select(layer: string, fn: string): void {
    const value = `${layer}\u0000${fn}`;
    if ([...this.picker.options].some((o) => o.value === value)) this.picker.value = value;
  }

  private arcClick(e: MouseEvent): void {
    const b = (e.target as HTMLElement).closest<HTMLElement>('[data-step-into]');
    if (!b) return;
    const fn = b.dataset.stepInto as string;
    const tick = Number(b.closest<HTMLElement>('[data-tick]')?.dataset.tick ?? this.app.store.selectedTick);
    const layer = this.app.engine.functions.find((f) => f.name === fn)?.layer ?? '';
    void this.open(layer, fn, tick);
  }

  private key(e: KeyboardEvent): void {
    if (!this.replay || e.ctrlKey || e.metaKey || e.altKey || isTyping(e.target)) return;
    let handled = true;
    if (e.key === 'F10') this.act('block');
    else if (e.key === 'F11') this.act(e.shiftKey ? 'out' : 'into');
    else if (e.key === 'F8') {
      if (e.shiftKey) this.restart();
      else this.act('end');
    } else if (e.key === 'Escape' && !byId('side-pane').contains(e.target as Node) && this.app.store.mode === 'solve') this.close();
    else handled = false;
    if (handled) e.preventDefault();
  }

  // ---------- Drawing ----------

  private render(): void {
    const r = this.replay;
    for (const b of Object.values(this.buttons)) b.disabled = !r;
    if (!r) return this.renderIdle();
    const v = r.view;
    const { plan } = r;
    this.startGroup.hidden = true;
    this.controls.hidden = false;
    for (const k of ['block', 'into', 'out', 'end'] as const) this.buttons[k].disabled = v.done;
    this.title.replaceChildren(el('b', undefined, plan.function), el('span', 'dbg-sub', ` layer ${plan.layer} · tick ${plan.tick}`), this.chip(v));
    this.root.dataset.block = v.blockId ?? '';
    this.root.dataset.state = v.busy ? 'busy' : v.done ? (v.error ? 'error' : 'done') : 'paused';
    this.codeLines.forEach((li, i) => li.classList.toggle('current', i === v.line));
    if (v.line !== null) this.codeLines[v.line]?.scrollIntoView({ block: 'nearest' });
    this.renderVars(v, v.done ? r.lastFrames : v.frames);
    this.renderSide(r);
    if (this.body.firstElementChild !== this.code) this.body.replaceChildren(this.code, this.vars, this.side);
    const blockId = v.done ? (v.error?.blockId ?? null) : v.blockId;
    if (!v.busy) this.app.paneArea.highlightStep({ layer: plan.layer, function: plan.function, blockId });
  }

  private chip(v: StepView): HTMLElement {
    if (v.busy) return el('span', 'dbg-chip busy', 'running…');
    if (v.error) return el('span', 'dbg-chip err', 'stopped with an error');
    if (v.done) return el('span', 'dbg-chip ok', 'returned');
    if (v.blockId === null) return el('span', 'dbg-chip', 'not started');
    return el('span', 'dbg-chip', v.line === null ? 'paused' : `paused at line ${v.line + 1}`);
  }

  /** The panel without a replay: how to start one. */
  private renderIdle(): void {
    if (this.replay) return;
    this.root.dataset.state = 'idle';
    this.root.dataset.block = '';
    this.startGroup.hidden = false;
    this.controls.hidden = true;
    const tick = this.app.store.selectedTick;
    this.title.replaceChildren(el('span', 'dbg-sub', tick > 0 ? `at tick ${tick}` : 'Step the robot first, then select a tick after 0.'));
    this.startButton.disabled = tick < 1 || this.picker.options.length === 0;
    for (const b of Object.values(this.buttons)) b.disabled = true;
    const box = el('div', 'empty-state');
    const inner = el('div');
    inner.append(
      el('b', undefined, 'Step through a function, block by block'),
      this.picker.options.length === 0
        ? 'Open a controller and run it, then pick a function here.'
        : 'Pick a function and press Step into: it runs again with the inputs it had at the selected tick, and stops before each block. You can also step into a function from its arcs or its blocks.',
    );
    box.appendChild(inner);
    this.body.replaceChildren(box);
  }

  private message(text: string, title: string): void {
    this.title.replaceChildren(el('b', undefined, title));
    const box = el('div', 'empty-state', text);
    this.body.replaceChildren(box);
  }

  private fail(text: string): void {
    this.render();
    const box = el('div', 'empty-state dbg-problem');
    const inner = el('div');
    inner.append(el('b', undefined, 'Cannot step into this function'), text);
    box.appendChild(inner);
    this.body.replaceChildren(box);
  }

  private buildCode(): void {
    const r = this.replay as Replay;
    this.code = el('ol', 'dbg-code');
    this.code.setAttribute('aria-label', `Code of ${r.plan.function}`);
    this.codeLines = r.stepper.listing.lines.map((text) => {
      const li = el('li');
      li.appendChild(el('code', undefined, text || ' '));
      return li;
    });
    this.code.append(...this.codeLines);
  }

  private renderVars(v: StepView, frames: StepView['frames']): void {
    const table = el('table', 'dbg-locals');
    const cols = el('colgroup');
    cols.append(el('col', 'c-name'), el('col'));
    table.appendChild(cols);
    const body = el('tbody');
    const heading = (text: string, className: string): void => {
      const tr = el('tr', className);
      const td = el('td', undefined, text);
      td.colSpan = 2;
      tr.appendChild(td);
      body.appendChild(tr);
    };
    const GROUPS: Record<Local['kind'], string> = { input: 'Inputs', parameter: 'Parameters', layer: 'Layer variables', variable: 'Variables' };
    // Block variables first: they are what changes from step to step.
    const rank: Record<Local['kind'], number> = { variable: 0, input: 1, parameter: 1, layer: 2 };
    frames.forEach((frame, i) => {
      if (frames.length > 1) heading(i === 0 ? `In ${frame.function} (helper)` : `In ${frame.function}`, 'dbg-frame');
      let kind: Local['kind'] | null = null;
      for (const l of [...frame.locals].sort((a, b) => rank[a.kind] - rank[b.kind])) {
        if (l.kind !== kind) heading(GROUPS[(kind = l.kind)], 'dbg-group');
        body.appendChild(this.localRow(l));
      }
    });
    table.appendChild(body);
    if (frames.length === 0 || frames.every((f) => f.locals.length === 0)) {
      this.vars.replaceChildren(el('div', 'dbg-note', v.done ? 'The call has ended. Restart to step through it again.' : 'No variables yet.'));
    } else if (v.done) {
      this.vars.replaceChildren(el('div', 'dbg-note', 'The values where it last paused:'), table);
    } else this.vars.replaceChildren(table);
  }

  private localRow(l: Local): HTMLElement {
    const tr = el('tr', `k-${l.kind}`);
    tr.dataset.name = l.name;
    const name = el('td', 'name', l.name);
    const text = l.problem ? `(${l.problem})` : l.value === undefined ? 'not set yet' : shortValue(l.value);
    const value = el('td', l.value === undefined ? 'value unset' : 'value', text);
    value.title = l.problem ?? (l.value === undefined ? 'not set yet' : formatValue(l.value, 2000));
    tr.append(name, value);
    return tr;
  }

  private renderSide(r: Replay): void {
    const v = r.view;
    const parts: HTMLElement[] = [];
    if (v.done) parts.push(this.outcome(v, r.plan.recorded));
    else if (r.plan.text && v.blockId === null) parts.push(el('div', 'dbg-note', 'This function is written as text: it has no blocks to stop at.'));
    const printed = el('div', 'dbg-printed');
    printed.appendChild(el('h3', undefined, `Printed (${v.printed.length})`));
    if (v.printed.length === 0) printed.appendChild(el('div', 'dbg-note', 'Nothing printed yet.'));
    else {
      const list = el('ol');
      for (const line of v.printed) list.appendChild(el('li', undefined, line));
      printed.appendChild(list);
    }
    parts.push(printed);
    this.side.replaceChildren(...parts);
  }

  /** The result (or error) and how it compares with the run. */
  private outcome(v: StepView, recorded: Recorded): HTMLElement {
    const box = el('div', 'dbg-result');
    if (v.error) {
      box.classList.add('err');
      box.append(el('h3', undefined, 'Stopped with an error'), el('div', 'dbg-msg', v.error.message));
    } else {
      box.append(el('h3', undefined, 'Returned'));
      const value = el('code', 'dbg-value', formatValue(v.result, 300));
      value.dataset.result = JSON.stringify(v.result) ?? 'undefined';
      box.appendChild(value);
    }
    let same: boolean | null = null;
    let text: string;
    if (recorded.kind === 'unknown') text = recorded.why;
    else if (recorded.kind === 'error') {
      same = v.error !== undefined && v.error.message === recorded.error.message;
      text = same ? 'Same as the run: it stopped with this error at this tick.' : `The run stopped here with: ${recorded.error.message}`;
    } else {
      same = v.error === undefined && sameValue(v.result, recorded.value);
      text = `${same ? 'Same as the run' : 'The run recorded'}: ${formatValue(recorded.value, 200)}`;
    }
    const cmp = el('div', `dbg-compare ${same === null ? '' : same ? 'same' : 'differs'}`, text);
    if (same !== null) cmp.dataset.same = String(same);
    box.appendChild(cmp);
    return box;
  }
}
