/**
 * The app: wires the store, the engine Worker, the world view and the panels. It never changes
 * engine state itself: it sends commands and draws what the engine reports, once per animation
 * frame at most, so the page stays smooth however fast the robot runs.
 */
import type { ControllerSpec } from '../../core/controller/model';
import type { ControllerError } from '../../core/session/types';
import type { WorldEdit } from '../../core/world/edits';
import type { Hit } from '../create/hit';
import { Inspector } from '../create/inspector';
import { PlanEditor } from '../create/plan-editor';
import { PointerInput } from '../create/pointer';
import { CreateState } from '../create/selection';
import { ToolsPanel } from '../create/tools-panel';
import { installDebugger } from '../debugger/index';
import { diagramPane } from '../diagram/index';
import { editorPanes } from '../editor/index';
import { packPanes } from '../packs/editor-pane';
import type { ArcRow } from '../engine/client';
import { EngineClient } from '../engine/client';
import { Autosave } from '../files/autosave';
import type { Platform } from '../files/platform';
import { AboutPanel } from '../panels/about';
import { ArcTable } from '../panels/arc-table';
import { byId } from '../panels/dom';
import { ErrorsPanel } from '../panels/errors';
import { OutputPanel } from '../panels/output';
import { OverlayPicker } from '../panels/overlay-picker';
import { RunSummary } from '../panels/run-summary';
import { DockTabs } from '../panels/tabs';
import { Timeline } from '../panels/timeline';
import { PaneArea } from '../panes/pane-area';
import type { EditRestrictions, PaneHost } from '../panes/types';
import type { WorldPicture } from '../world-view/picture';
import type { EditMarks } from '../world-view/view';
import { WorldView } from '../world-view/view';
import { Documents } from './documents';
import { Emitter } from './emitter';
import { FileMenu } from './file-menu';
import { installKeys } from './keys';
import { boundsOf, pictureOfFrame, pictureOfSpec, withDraft } from './picture';
import { Store } from './store';
import { Toolbar } from './toolbar';

/** Ticks one press of Run computes at most before pausing (keeps a wandering robot's history bounded). */
const RUN_LIMIT = 50_000;
/** Ticks one run may hold at most (a few tens of MB of history): memory stays bounded however often Run is pressed. */
const MAX_RUN_TICKS = 200_000;

export class App {
  readonly store: Store;
  readonly engine = new EngineClient();
  readonly view = new WorldView(byId('world-host'));
  readonly create = new CreateState();
  readonly docs: Documents;
  private readonly autosave: Autosave;
  private toolbar!: Toolbar;
  private timeline!: Timeline;
  private arcTable!: ArcTable;
  private output!: OutputPanel;
  private errors!: ErrorsPanel;
  private overlay!: OverlayPicker;
  private summary!: RunSummary;
  private about!: AboutPanel;
  private dock!: DockTabs;
  private panes!: PaneArea;
  private draft: WorldEdit | null = null;
  private uiDirty = true;
  private pictureDirty = true;
  private aboutDirty = true;
  private outputUpTo = 0;
  private arcsInFlight = false;
  private arcsAskedAt = 0;
  private arcsShownFor = -1;
  private lastArcs: { tick: number; rows: readonly ArcRow[] } = { tick: -1, rows: [] };
  private scrolledTick = -1;
  private runError: ControllerError | null = null;
  private readonly onRunError = new Emitter<ControllerError | null>();
  private readonly onControllerOpened = new Emitter<ControllerSpec | null>();
  private restrictions: EditRestrictions | null = null;
  private readonly onRestrictions = new Emitter<EditRestrictions | null>();
  /** The step-by-step debugger sets this: replays a function at the selected tick. */
  stepIntoHandler: ((layer: string, fn: string) => void) | null = null;
  private fitPending = true;
  /** While restoring, documents open without loading the engine each time; start() loads once. */
  private starting = true;
  private summaryKey = '';
  private pictureChangedSinceSummary = true;

  constructor(private readonly platform: Platform) {
    this.store = new Store({ name: 'Untitled world', walls: [], goals: [], plan: [], robot: { x: 0, y: 0, heading: 90 } });
    this.docs = new Documents(this.store, platform);
    this.autosave = new Autosave(platform);
  }

  async start(initial: () => Promise<void>): Promise<void> {
    await this.view.init();
    this.view.beforeFrame = () => this.frame();
    this.buildPanels();
    this.wire();
    const saved = await this.autosave.restore();
    if (saved) {
      this.store.openWorld(saved.world, saved.worldSource);
      this.store.openController(saved.controller, saved.controllerSource);
      this.store.setMode(saved.mode);
    } else {
      await initial();
    }
    this.applyMode();
    this.starting = false;
    // Ready means the engine holds the restored world and controller (the tests rely on it).
    const loaded = new Promise<void>((resolve) => {
      const off = this.engine.onLoaded.on(() => {
        off();
        resolve();
      });
    });
    this.loadEngine();
    await loaded;
  }

  private buildPanels(): void {
    this.toolbar = new Toolbar(this);
    new FileMenu(this.docs, this.platform);
    this.timeline = new Timeline((t) => this.store.select(t, false));
    this.arcTable = new ArcTable(byId('arc-panel'));
    this.output = new OutputPanel(byId('output-panel'), byId('output-count'));
    this.errors = new ErrorsPanel(byId('error-panel'), byId('error-count'), (e) => this.revealError(e));
    this.overlay = new OverlayPicker(() => this.showArcs(true));
    this.summary = new RunSummary();
    this.dock = new DockTabs(byId('dock'));
    this.about = new AboutPanel(byId('about-panel'));
    installDebugger(this);
    new ToolsPanel(this.create, this.store);
    new Inspector(this.create, this.store);
    new PlanEditor(this.store);
    this.panes = new PaneArea(byId('pane-tabs'), byId('pane-body'), [...editorPanes(), diagramPane(), ...packPanes()], this.paneHost());
    new PointerInput({
      view: this.view,
      create: this.create,
      mode: () => this.store.mode,
      picture: () => this.currentPicture(),
      setDraft: (edit) => {
        this.draft = edit;
        this.pictureDirty = true;
        this.invalidate();
      },
      commit: (edit) => this.commitEdit(edit),
      placeGoal: (x, y) => this.placeGoal(x, y),
      remove: (hit) => this.remove(hit),
    });
    installKeys(this);
  }

  private paneHost(): PaneHost {
    return {
      controller: () => this.store.controller,
      updateController: (spec) => {
        this.store.controller = spec;
        this.store.onController.emit();
      },
      onControllerOpened: (fn) => this.onControllerOpened.on(fn),
      selectedTick: () => this.store.selectedTick,
      onTickSelected: (fn) => this.store.onSelect.on(fn),
      arcs: (tick) => this.engine.arcs(tick),
      functions: () => this.engine.functions,
      onError: (fn) => this.onRunError.on(fn),
      notice: (text, kind) => this.store.notice(text, kind),
      showPane: (id) => this.panes.show(id),
      restrictions: () => this.restrictions,
      onRestrictionsChanged: (fn) => this.onRestrictions.on(fn),
      stepInto: (layer, fn) => {
        if (this.stepIntoHandler) this.stepIntoHandler(layer, fn);
        else this.store.notice('The step-by-step debugger is not available.', 'error');
      },
      openFunction: (layer, fn) => this.panes.openFunction(layer, fn),
    };
  }

  private wire(): void {
    const s = this.store;
    s.onWorld.on(({ reason }) => {
      this.pictureDirty = true;
      this.aboutDirty = true;
      if (reason === 'document') this.fitPending = true;
      // The engine follows the designed world: Reset and Run start from it.
      if (!this.starting) this.engine.reset(s.world);
      this.saveSoon();
      this.invalidate();
    });
    s.onController.on(() => {
      this.aboutDirty = true;
      if (!this.starting) this.loadEngine();
      this.saveSoon();
    });
    s.onMode.on(() => {
      this.applyMode();
      this.saveSoon();
    });
    s.onSelect.on(() => {
      this.pictureDirty = true;
      this.invalidate();
    });
    this.engine.onLoaded.on(() => {
      this.pictureChangedSinceSummary = true;
      this.output.clear();
      this.outputUpTo = 0;
      this.lastArcs = { tick: -1, rows: [] };
      this.arcsShownFor = -1;
      this.view.overlay.clear();
      this.store.select(0, true);
      this.pictureDirty = true;
      this.invalidate();
    });
    this.engine.onTicks.on(() => {
      this.pictureDirty = true;
      this.invalidate();
    });
    this.engine.onStatus.on(() => this.invalidate());
    this.engine.onProblem.on((m) => {
      this.errors.addProblem(m);
      this.store.notice(m.split('\n')[0], 'error');
    });
    this.create.onChange.on(() => this.invalidate());
    // An example opened from the menu (not the first start's defaults): show what it is for first.
    this.docs.onExampleOpened.on(() => {
      if (!this.starting) this.dock.show('about');
    });
  }

  /** What the open challenge locks and offers (null: no challenge, nothing restricted). */
  get editRestrictions(): EditRestrictions | null {
    return this.restrictions;
  }

  /** Sets what the open challenge locks and offers (null: no challenge, nothing restricted). */
  setRestrictions(r: EditRestrictions | null): void {
    this.restrictions = r;
    this.onRestrictions.emit(r);
  }

  /** The right-hand pane (the debugger highlights blocks through it). */
  get paneArea(): PaneArea {
    return this.panes;
  }

  /** Loads the world and the controller into a fresh engine session. */
  loadEngine(): void {
    this.errors.clearProblems();
    this.onControllerOpened.emit(this.store.controller);
    this.engine.load(this.store.world, this.store.controller);
  }

  private applyMode(): void {
    const mode = this.store.mode;
    byId('app').dataset.mode = mode;
    if (mode === 'create') this.engine.stop();
    else this.create.select(null);
    this.draft = null;
    this.view.setTrailVisible(mode === 'solve');
    if (mode === 'create') this.view.overlay.clear();
    else this.showArcs(true);
    this.pictureDirty = true;
    this.invalidate();
  }

  invalidate(): void {
    this.uiDirty = true;
    this.view.invalidate();
  }

  private saveSoon(): void {
    const s = this.store;
    this.autosave.schedule(() => ({ world: s.world, worldSource: s.worldSource, controller: s.controller, controllerSource: s.controllerSource, mode: s.mode }));
  }

  // ---------- Commands from the toolbar and the keys ----------

  /** Run or Stop. */
  toggleRun(): void {
    if (this.engine.state.running) return this.engine.stop();
    const left = this.ticksLeft();
    if (left > 0) this.engine.run(this.toolbar.speed(), Math.min(RUN_LIMIT, left));
  }

  step(): void {
    if (this.ticksLeft() > 0) this.engine.step();
  }

  /** How many more ticks the run may take (0 after saying why it cannot go on); shows the newest tick. */
  private ticksLeft(): number {
    this.store.setMode('solve');
    if (!this.engine.state.hasController) return this.refuse('Open a controller first (File › Example controllers).', 'error');
    if (this.engine.state.status !== 'ready') return this.refuse('The run has ended. Press Reset (R) to start again.');
    const latest = this.engine.frames.length - 1;
    if (latest >= MAX_RUN_TICKS) return this.refuse(`This run holds ${MAX_RUN_TICKS.toLocaleString('en')} ticks, the most one run keeps. Press Reset (R) to start again.`);
    this.store.select(latest, true);
    return MAX_RUN_TICKS - latest;
  }

  private refuse(text: string, kind?: 'info' | 'error'): 0 {
    this.store.notice(text, kind);
    return 0;
  }

  reset(): void {
    this.engine.reset();
  }

  setSpeed(speed: number): void {
    if (this.engine.state.running) this.engine.setSpeed(speed);
  }

  /** Moves the selected tick by `delta`, or steps when moving forward from the newest tick. */
  nudge(delta: number, stepAtEnd: boolean): void {
    const latest = this.engine.frames.length - 1;
    const t = this.store.selectedTick + delta;
    if (delta > 0 && this.store.selectedTick >= latest && stepAtEnd) return this.step();
    this.store.select(Math.max(0, Math.min(latest, t)), t >= latest && this.engine.state.running);
  }

  selectLast(): void {
    this.store.select(this.engine.frames.length - 1, true);
  }

  fit(): void {
    const frame = this.engine.frames[this.store.selectedTick];
    const parts = frame ? this.engine.worldAt(frame) : null;
    const spec = this.store.mode === 'create' || !parts ? this.store.world : { ...this.store.world, walls: parts.walls, goals: parts.goals };
    this.view.fit(boundsOf(spec));
  }

  deleteSelection(): void {
    const s = this.create.selection;
    if (this.store.mode !== 'create' || !s) return;
    if (s.kind === 'goal') this.remove({ kind: 'goal', name: s.name });
    else if (s.kind === 'wall') this.remove({ kind: 'wall', index: s.index });
  }

  private revealError(e: ControllerError): void {
    if (!this.panes.revealError(e)) this.store.notice(`The error is in function “${e.function}” (layer ${e.layer}).`);
    if (e.tick < this.engine.frames.length) this.store.select(e.tick, false);
  }

  // ---------- Edits ----------

  private commitEdit(edit: WorldEdit): void {
    if (this.store.mode === 'create') this.store.editWorld(edit);
    else this.engine.editWorld(edit); // Recorded by the session at its current tick.
  }

  private placeGoal(x: number, y: number): void {
    const names = new Set(this.store.world.goals.map((g) => g.name));
    let i = names.size + 1;
    while (names.has(`goal${i}`)) i++;
    const name = `goal${i}`;
    if (this.store.editWorld({ type: 'addGoal', goal: { name, x, y } })) {
      this.create.select({ kind: 'goal', name });
      this.create.onNameGoal.emit(name);
    }
  }

  private remove(hit: Hit): void {
    if (this.store.mode !== 'create') return;
    if (hit.kind === 'goal') this.store.editWorld({ type: 'removeGoal', name: hit.name });
    else if (hit.kind === 'wall' || hit.kind === 'wallEnd') this.store.editWorld({ type: 'removeWall', index: hit.index });
    else if (hit.kind === 'robot') return this.store.notice('The world needs its robot: move it instead.');
    this.create.select(null);
  }

  // ---------- Drawing, once per animation frame ----------

  private picture: WorldPicture | null = null;

  private currentPicture(): WorldPicture | null {
    if (this.pictureDirty) this.computePicture();
    return this.picture;
  }

  private computePicture(): void {
    this.pictureDirty = false;
    if (this.store.mode === 'create') {
      this.picture = pictureOfSpec(withDraft(this.store.world, this.draft));
      return;
    }
    const frame = this.engine.frames[Math.min(this.store.selectedTick, this.engine.frames.length - 1)];
    this.picture = frame ? pictureOfFrame(frame, this.engine.worldAt(frame), this.draft) : pictureOfSpec(this.store.world);
  }

  private frame(): void {
    if (!this.uiDirty) return;
    this.uiDirty = false;
    if (this.aboutDirty) {
      this.aboutDirty = false;
      this.about.show(this.store.world, this.store.controller);
    }
    const frames = this.engine.frames;
    const latest = frames.length - 1;
    if (this.store.follow && this.store.selectedTick !== latest && latest >= 0) this.store.select(latest, true);
    if (this.store.selectedTick > latest) this.store.select(Math.max(0, latest), true);
    const tick = this.store.selectedTick;
    const solve = this.store.mode === 'solve';
    if (this.pictureDirty) this.computePicture();
    if (this.picture) this.view.setPicture(this.picture);
    this.view.setTrail(frames, solve ? tick + 1 : 0);
    if (this.fitPending && this.picture) {
      this.fitPending = false;
      this.fit();
    }
    this.view.setEditMarks(solve ? null : this.marks());
    this.timeline.show(tick, Math.max(0, latest));
    const frame = frames[tick];
    const summaryKey = `${tick}/${latest}/${this.engine.state.hasController}/${frame?.worldRev}/${this.store.mode}`;
    if (summaryKey !== this.summaryKey || this.pictureChangedSinceSummary) {
      this.summaryKey = summaryKey;
      this.summary.show(frame, frame ? this.engine.worldAt(frame) : undefined, latest, this.engine.state.hasController);
    }
    this.pictureChangedSinceSummary = false;
    if (this.outputUpTo < frames.length) {
      this.output.append(frames.slice(this.outputUpTo));
      this.outputUpTo = frames.length;
    }
    const scroll = !this.store.follow && this.scrolledTick !== tick;
    this.output.highlight(tick, scroll);
    this.scrolledTick = tick;
    const err = frames[latest]?.error ?? null;
    if (err !== this.runError) {
      this.runError = err;
      this.errors.setRunError(err);
      this.onRunError.emit(err);
    }
    this.toolbar.render(this.engine.state, tick, latest, this.view.fps);
    byId('world-title').textContent = this.store.world.name;
    byId('doc-world').textContent = this.store.worldSource.name;
    byId('doc-controller').textContent = this.store.controllerSource?.name ?? (this.store.controller ? this.store.controller.name : 'none');
    this.requestArcs();
  }

  private marks(): EditMarks {
    const s = this.create.selection;
    const p = this.picture;
    const handles: [number, number][] = [];
    if (s?.kind === 'wall' && p?.walls[s.index]) {
      const w = p.walls[s.index];
      handles.push([w[0][0], w[0][1]], [w[1][0], w[1][1]]);
    }
    const preview = this.draft?.type === 'addWall' ? ([this.draft.wall[0][0], this.draft.wall[0][1], this.draft.wall[1][0], this.draft.wall[1][1]] as const) : null;
    return {
      selectedWall: s?.kind === 'wall' ? s.index : null,
      selectedGoal: s?.kind === 'goal' ? s.name : null,
      robotSelected: s?.kind === 'robot',
      preview,
      handles,
    };
  }

  /** Fetches the selected tick's arcs, one request at a time (the newest selection wins). */
  private requestArcs(): void {
    const tick = this.store.selectedTick;
    // While running, a few arc tables a second are plenty to read; each costs a table layout.
    const throttled = this.engine.state.running && performance.now() - this.arcsAskedAt < 120;
    if (throttled) setTimeout(() => this.invalidate(), 130);
    if (throttled || this.arcsInFlight || this.lastArcs.tick === tick || !this.engine.state.hasController) {
      if (!this.engine.state.hasController && this.arcsShownFor !== -2) {
        this.arcsShownFor = -2;
        this.arcTable.empty('No controller is running', 'Open a controller to see the values on its arcs.');
      }
      return;
    }
    this.arcsInFlight = true;
    this.arcsAskedAt = performance.now();
    void this.engine.arcs(tick).then((rows) => {
      this.arcsInFlight = false;
      this.lastArcs = { tick, rows };
      this.showArcs(false);
      if (this.store.selectedTick !== tick) this.invalidate();
    });
  }

  private showArcs(force: boolean): void {
    const { tick, rows } = this.lastArcs;
    if (tick < 0) return;
    if (force || this.arcsShownFor !== tick) {
      this.arcsShownFor = tick;
      this.arcTable.show(tick, rows);
    }
    const choice = this.store.mode === 'solve' ? this.overlay.update(rows) : null;
    if (choice) this.view.overlay.show(choice.value, choice.field, choice.grid, choice.kind, this.view.colors.robotEdge);
    else this.view.overlay.clear();
    this.view.invalidate();
  }
}
