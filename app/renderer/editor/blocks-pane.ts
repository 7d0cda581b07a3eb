/**
 * The Blocks pane: the controller as layer blocks holding function blocks (the controller
 * workspace), and one function's body at a time (the body workspace, or a text editor for a
 * text-mode function). The controller workspace is the truth for the layers: its function blocks
 * carry their bodies as extra state, and every change is read back with `workspaceToController`
 * and handed to the session (which sends it to the app). Each workspace keeps its own undo.
 */
import * as Blockly from 'blockly/core';
import type { ControllerSpec, FunctionSpec, LayerSpec } from '../../core/controller/model';
import { validateController } from '../../core/controller/validate';
import { formatProblems } from '../../core/formats/types';
import { parseController } from '../../core/formats';
import type { ControllerError } from '../../core/session/types';
import type { JsonValue, ValueType } from '../../core/values';
import { emptyBody } from '../../../blocks/build';
import type { FunctionContext } from '../../../blocks/context';
import { setFunctionContext } from '../../../blocks/context';
import { ARC_BLOCK, CONTROLLER_FUNCTION_BLOCK, functionExtra, OPEN_FIELD, setFunctionExtra, setOpenFunctionHandler } from '../../../blocks/controller/function';
import { LAYER_BLOCK, LAYER_VARIABLE_DEF_BLOCK, RANDOM_SOURCE_BLOCK } from '../../../blocks/controller/layer';
import { FieldNameDropdown } from '../../../blocks/fields/name-dropdown';
import { generateBody, loadBody } from '../../../blocks/generate';
import { registerLayerbotBlocks } from '../../../blocks/index';
import { makeControllerToolbox, makeToolbox } from '../../../blocks/toolbox';
import { COLOURS } from '../../../blocks/types';
import { controllerToWorkspace, layerState, workspaceToController } from '../../../blocks/workspace';
import { el } from '../panels/dom';
import { functionOptionGroups } from './pickers';
import type { ControllerPane, PaneHost, StepPoint } from '../panes/types';
import { alertDialog, chooseDialog, confirmDialog, promptDialog } from './dialog';
import { icon, LOCK_BADGE, TEXT_BADGE } from './icons';
import type { FunctionRef } from './model';
import { copyLayerInto, isFunctionLocked, isLayerLocked, lockViolation, renamedSource, textBodyOf, uniqueName } from './model';
import type { EditorSession } from './session';
import { isContrast, onThemeChange, pageTheme, recolour } from './theme';
import { expandButton, TextEditor } from './text-editor';

const LOCK_FIELD = 'LB_LOCK';
const TEXT_FIELD = 'LB_TEXT';
const SYNC_DELAY_MS = 120;
const DOUBLE_CLICK_MS = 400;

type View = 'controller' | 'function';

/** The function open in the body view: its block in the controller workspace, and where it is. */
interface Opened {
  readonly blockId: string;
  ref: FunctionRef;
  /** Its blocks could not be loaded: never save the (empty) workspace over them. */
  broken: boolean;
}

let dialogsInstalled = false;

/** Blockly asks for variable names through window.prompt, which Electron lacks: use our dialogs. */
function installDialogs(): void {
  if (dialogsInstalled) return;
  dialogsInstalled = true;
  Blockly.dialog.setPrompt((message, value, callback) => void promptDialog('Layerbot', message, value).then(callback));
  Blockly.dialog.setConfirm((message, callback) => void confirmDialog('Layerbot', message).then(callback));
  Blockly.dialog.setAlert((message, callback) => void alertDialog('Layerbot', message).then(() => callback?.()));
}

/** The controller workspace's toolbox: the controller blocks in three small categories. */
function controllerToolbox(): Blockly.utils.toolbox.ToolboxDefinition {
  const items = (makeControllerToolbox() as { contents: Blockly.utils.toolbox.ToolboxItemInfo[] }).contents;
  const pick = (...types: string[]) => items.filter((i) => types.includes((i as { type?: string }).type ?? ''));
  return {
    kind: 'categoryToolbox',
    contents: [
      { kind: 'category', name: 'Layers', colour: String(COLOURS.layer), contents: pick(LAYER_BLOCK, LAYER_VARIABLE_DEF_BLOCK) },
      { kind: 'category', name: 'Functions', colour: String(COLOURS.function), contents: pick(CONTROLLER_FUNCTION_BLOCK, ARC_BLOCK) },
      { kind: 'category', name: 'Random', colour: String(COLOURS.random), contents: pick(RANDOM_SOURCE_BLOCK) },
    ],
  } as Blockly.utils.toolbox.ToolboxDefinition;
}

function button(label: string, iconName: Parameters<typeof icon>[0] | null, title: string, cls = 'lbe-btn'): HTMLButtonElement {
  const b = el('button', cls);
  b.type = 'button';
  b.title = title;
  if (iconName) b.appendChild(icon(iconName));
  if (label) b.appendChild(el('span', '', label));
  else b.setAttribute('aria-label', title);
  return b;
}

/** The layer block a block sits in (a function, an arc, a variable), or null. */
function layerBlockOf(block: Blockly.Block | null): Blockly.Block | null {
  for (let b = block; b; b = b.getSurroundParent()) if (b.type === LAYER_BLOCK) return b;
  return null;
}

function functionBlockOf(block: Blockly.Block | null): Blockly.Block | null {
  for (let b = block; b; b = b.getSurroundParent()) if (b.type === CONTROLLER_FUNCTION_BLOCK) return b;
  return null;
}

function statementChildren(block: Blockly.Block, input: string): Blockly.Block[] {
  const out: Blockly.Block[] = [];
  for (let b = block.getInputTargetBlock(input); b; b = b.getNextBlock()) out.push(b);
  return out;
}

const nameOf = (block: Blockly.Block): string => String(block.getFieldValue('NAME') ?? '');

/** Where a function block is: its layer's name and its own. */
function refOf(block: Blockly.Block): FunctionRef {
  const layer = layerBlockOf(block);
  return { layer: layer ? nameOf(layer) : '', fn: nameOf(block) };
}

/** What the body workspace of a function block knows (names from the blocks, so they are current). */
function contextFromBlock(block: Blockly.Block): FunctionContext {
  const layer = layerBlockOf(block);
  const output = String(block.getFieldValue('OUTPUT')) as ValueType;
  return {
    name: nameOf(block),
    output,
    inputs: statementChildren(block, 'ARCS').map(nameOf),
    variables: layer ? statementChildren(layer, 'VARIABLES').map(nameOf) : [],
  };
}

/** A function spec read from its block (for generating its code), with the layer's variables. */
function specsFromBlock(block: Blockly.Block): { fn: FunctionSpec; layer: LayerSpec } {
  const layerBlock = layerBlockOf(block);
  const variables = layerBlock
    ? statementChildren(layerBlock, 'VARIABLES').map((v) => {
        let value: JsonValue = null;
        try {
          value = JSON.parse(String(v.getFieldValue('VALUE'))) as JsonValue;
        } catch {
          value = null;
        }
        return { name: nameOf(v), value };
      })
    : [];
  const extra = functionExtra(block);
  const fn: FunctionSpec = {
    name: nameOf(block),
    output: String(block.getFieldValue('OUTPUT')) as ValueType,
    inputs: statementChildren(block, 'ARCS').map((a) => ({ name: nameOf(a), from: { kind: 'world', input: 'tick' } })),
    body: extra.body ?? { kind: 'blocks', blocks: emptyBody() },
  };
  return { fn, layer: { name: layerBlock ? nameOf(layerBlock) : '', variables, randomSources: [], functions: [fn] } };
}

/** Scrolls a workspace so its blocks start near the top left corner. */
function scrollToStart(ws: Blockly.WorkspaceSvg): void {
  if (ws.getTopBlocks(false).length === 0) return;
  const box = ws.getBlocksBoundingBox();
  ws.scroll(-box.left * ws.scale + 12, -box.top * ws.scale + 12);
}

const editorsByWorkspace = new WeakMap<Blockly.Workspace, BlocksPane>();
let menuInstalled = false;

/** "Open blocks" and "Step into" in a function block's context menu. */
function installContextMenu(): void {
  if (menuInstalled) return;
  menuInstalled = true;
  const paneOf = (scope: Blockly.ContextMenuRegistry.Scope): { pane: BlocksPane; block: Blockly.BlockSvg } | null => {
    const block = scope.block;
    if (!block || block.type !== CONTROLLER_FUNCTION_BLOCK || block.isInFlyout) return null;
    const pane = editorsByWorkspace.get(block.workspace);
    return pane ? { pane, block } : null;
  };
  Blockly.ContextMenuRegistry.registry.register({
    id: 'layerbot_open_function',
    scopeType: Blockly.ContextMenuRegistry.ScopeType.BLOCK,
    displayText: 'Open blocks',
    weight: -10,
    preconditionFn: (scope) => (paneOf(scope) ? 'enabled' : 'hidden'),
    callback: (scope) => {
      const p = paneOf(scope);
      if (p) p.pane.openBlock(p.block.id);
    },
  });
  Blockly.ContextMenuRegistry.registry.register({
    id: 'layerbot_step_into',
    scopeType: Blockly.ContextMenuRegistry.ScopeType.BLOCK,
    displayText: 'Step into at the selected tick',
    weight: -9,
    preconditionFn: (scope) => (paneOf(scope) ? 'enabled' : 'hidden'),
    callback: (scope) => {
      const p = paneOf(scope);
      if (p) p.pane.stepInto(refOf(p.block));
    },
  });
}

export class BlocksPane implements ControllerPane {
  readonly id = 'blocks';
  readonly title = 'Blocks';
  private host!: PaneHost;
  private root!: HTMLElement;
  private crumbs!: HTMLElement;
  private undoBtn!: HTMLButtonElement;
  private redoBtn!: HTMLButtonElement;
  private ctrlBar!: HTMLElement;
  private fnBar!: HTMLElement;
  private jump!: HTMLSelectElement;
  private modeBlocks!: HTMLButtonElement;
  private modeText!: HTMLButtonElement;
  private lockBadge!: HTMLElement;
  private banner!: HTMLElement;
  private ctrlDiv!: HTMLElement;
  private bodyDiv!: HTMLElement;
  private text!: TextEditor;
  private fileInput!: HTMLInputElement;
  private empty!: HTMLElement;

  private ctrlWs: Blockly.WorkspaceSvg | null = null;
  private bodyWs: Blockly.WorkspaceSvg | null = null;
  private view: View = 'controller';
  private opened: Opened | null = null;
  private visible = false;
  /** The controller workspace must be rebuilt from the session's spec (done when visible). */
  private reloadPending = true;
  /** The spec the locks are checked against (as loaded: locked parts never change here). */
  private baseline: ControllerSpec | null = null;
  private syncTimer: ReturnType<typeof setTimeout> | null = null;
  private bodyTimer: ReturnType<typeof setTimeout> | null = null;
  private lastClick = { id: '', at: 0 };
  /** Blocks a function had before it was switched to text (to go back to them). */
  private readonly blocksBeforeText = new Map<string, JsonValue>();
  private bodyNote: { text: string; kind: 'error' | 'warn' } | null = null;
  private runNote: string | null = null;

  constructor(private readonly session: EditorSession) {}

  mount(element: HTMLElement, host: PaneHost): void {
    this.host = host;
    this.session.attach(host);
    registerLayerbotBlocks();
    installDialogs();
    installContextMenu();
    this.build(element);
    this.session.onSpec.on((origin) => this.specChanged(origin));
    this.session.onRestrictions.on(() => this.applyRestrictions());
    this.session.onProblem.on(() => this.renderBanner());
    this.session.onError.on((e) => this.runErrorChanged(e));
    onThemeChange(() => recolour([this.ctrlWs, this.bodyWs].filter((w): w is Blockly.WorkspaceSvg => !!w)));
    this.renderBars();
  }

  shown(): void {
    this.visible = true;
    this.ensureWorkspaces();
    if (this.reloadPending) this.reload();
    this.resize();
  }

  hidden(): void {
    this.visible = false;
    this.flushBody();
    this.session.flush();
  }

  // ---------- DOM ----------

  private build(element: HTMLElement): void {
    this.root = el('div', 'lbe lbe-blocks');
    element.appendChild(this.root);

    const bar = el('div', 'lbe-bar');
    this.crumbs = el('nav', 'lbe-crumbs');
    this.crumbs.setAttribute('aria-label', 'Where you are');
    const tools = el('div', 'lbe-bar-tools');
    this.undoBtn = button('', 'undo', 'Undo (Ctrl+Z)', 'lbe-icon-btn');
    this.redoBtn = button('', 'redo', 'Redo (Ctrl+Y)', 'lbe-icon-btn');
    this.undoBtn.addEventListener('click', () => this.undo(false));
    this.redoBtn.addEventListener('click', () => this.undo(true));
    tools.append(this.undoBtn, this.redoBtn, expandButton());
    bar.append(this.crumbs, tools);

    this.ctrlBar = el('div', 'lbe-actions');
    const addLayer = button('Layer', 'plus', 'Add a layer at the bottom');
    addLayer.dataset.action = 'add-layer';
    addLayer.addEventListener('click', () => this.addLayer());
    const copy = button('Copy layer from file…', 'file', 'Add a copy of a layer from another controller file');
    copy.dataset.action = 'copy-layer';
    copy.addEventListener('click', () => this.fileInput.click());
    this.jump = el('select', 'lbe-select lbe-jump');
    this.jump.setAttribute('aria-label', 'Open a function');
    this.jump.title = 'Open a function’s blocks';
    this.jump.addEventListener('change', () => {
      const [layer, fn] = this.jump.value.split('\u0000');
      this.jump.value = '';
      if (fn !== undefined) this.openRef({ layer, fn });
    });
    this.ctrlBar.append(addLayer, copy, el('span', 'lbe-grow'), this.jump);

    this.fnBar = el('div', 'lbe-actions');
    const seg = el('div', 'lbe-seg');
    seg.setAttribute('role', 'group');
    seg.setAttribute('aria-label', 'How the function is written');
    this.modeBlocks = button('Blocks', 'blocks', 'Edit the function as blocks', 'lbe-seg-btn');
    this.modeText = button('JavaScript', 'code', 'Edit the function as JavaScript text', 'lbe-seg-btn');
    this.modeBlocks.dataset.mode = 'blocks';
    this.modeText.dataset.mode = 'text';
    this.modeBlocks.addEventListener('click', () => void this.switchMode('blocks'));
    this.modeText.addEventListener('click', () => void this.switchMode('text'));
    seg.append(this.modeBlocks, this.modeText);
    this.lockBadge = el('span', 'lbe-lock');
    this.lockBadge.append(icon('lock'), el('span', '', 'Locked'));
    this.lockBadge.title = 'This challenge locks this function: you can look at it and step into it, not change it.';
    const step = button('Step into', 'step', 'Run this function block by block at the selected tick');
    step.dataset.action = 'step-into';
    step.addEventListener('click', () => this.opened && this.stepInto(this.opened.ref));
    this.fnBar.append(seg, this.lockBadge, el('span', 'lbe-grow'), step);

    this.banner = el('div', 'lbe-banner');
    this.banner.setAttribute('role', 'status');

    const stage = el('div', 'lbe-stage');
    this.ctrlDiv = el('div', 'lbe-ws lbe-ctrl-ws');
    this.bodyDiv = el('div', 'lbe-ws lbe-body-ws');
    this.text = new TextEditor();
    this.empty = el('div', 'lbe-empty');
    this.empty.append(el('strong', '', 'No controller is open'), el('span', '', 'Open one from File › Example controllers, or start from an example and change it.'));
    stage.append(this.ctrlDiv, this.bodyDiv, this.text.element, this.empty);
    new ResizeObserver(() => this.resize()).observe(stage);

    this.fileInput = el('input');
    this.fileInput.type = 'file';
    this.fileInput.accept = '.json,application/json';
    this.fileInput.hidden = true;
    this.fileInput.addEventListener('change', () => void this.copyLayerFromFile());

    this.root.append(bar, this.ctrlBar, this.fnBar, this.banner, stage, this.fileInput);
    // Leaving the pane (towards Run, say) sends a pending edit at once.
    this.root.addEventListener('pointerleave', () => {
      this.flushBody();
      this.session.flush();
    });
    this.root.addEventListener('focusout', () => this.flushBody());
    this.text.onEdit = (code) => this.textEdited(code);
  }

  private ensureWorkspaces(): void {
    if (this.ctrlWs) return;
    const common: Blockly.BlocklyOptions = {
      media: 'media/',
      sounds: false,
      renderer: 'thrasos',
      theme: pageTheme(),
      trashcan: false,
      move: { scrollbars: true, drag: true, wheel: true },
      zoom: { controls: true, wheel: false, pinch: true, startScale: 0.8, maxScale: 2, minScale: 0.3, scaleSpeed: 1.15 },
      grid: { spacing: 24, length: 2, colour: isContrast() ? '#333333' : '#dfe4ec', snap: false },
    };
    this.ctrlWs = Blockly.inject(this.ctrlDiv, { ...common, zoom: { ...common.zoom, startScale: 0.72 }, toolbox: controllerToolbox(), comments: false, disable: false, collapse: true });
    this.bodyWs = Blockly.inject(this.bodyDiv, { ...common, toolbox: makeToolbox(this.toolboxCategories()), comments: true, disable: true, collapse: true });
    editorsByWorkspace.set(this.ctrlWs, this);
    setOpenFunctionHandler((block) => {
      if (block.workspace === this.ctrlWs) this.openBlock(block.id);
    });
    this.ctrlWs.addChangeListener((e) => this.controllerEvent(e));
    this.bodyWs.addChangeListener((e) => this.bodyEvent(e));
  }

  private resize(): void {
    if (!this.visible) return;
    if (this.ctrlWs && this.view === 'controller') Blockly.svgResize(this.ctrlWs);
    if (this.bodyWs && this.view === 'function') Blockly.svgResize(this.bodyWs);
  }

  // ---------- Loading ----------

  private specChanged(origin: string): void {
    if (origin === 'host') {
      this.reloadPending = true;
      if (this.visible) this.reload();
      return;
    }
    if (origin === 'code') {
      // A text body edited in the Code pane: keep the function block's copy in step.
      const ref = this.session.focus;
      const fn = ref && this.session.spec?.layers.find((l) => l.name === ref.layer)?.functions.find((f) => f.name === ref.fn);
      const block = ref ? this.functionBlock(ref) : null;
      if (fn && block) setFunctionExtra(block, { ...functionExtra(block), body: fn.body });
      if (this.opened && ref && this.opened.ref.fn === ref.fn && fn?.body.kind === 'text') this.text.setCode(fn.body.code);
    }
    this.renderBars();
  }

  /** Rebuilds the controller workspace from the session's spec (a controller was opened). */
  private reload(): void {
    this.ensureWorkspaces();
    this.reloadPending = false;
    const spec = this.session.spec;
    const ws = this.ctrlWs!;
    const wasOpen = this.opened?.ref ?? null;
    this.cancelTimers();
    this.opened = null;
    this.blocksBeforeText.clear();
    Blockly.Events.disable();
    try {
      if (spec) controllerToWorkspace(spec, ws);
      else ws.clear();
    } finally {
      Blockly.Events.enable();
    }
    ws.clearUndo();
    this.baseline = spec;
    this.applyRestrictions();
    this.decorateAll();
    scrollToStart(ws);
    this.empty.hidden = !!spec;
    // Stay in the same function when the new controller has it (a re-opened file, a restore).
    const again = wasOpen && spec ? this.functionBlock(wasOpen) : null;
    if (again) this.openBlock(again.id);
    else this.showController();
  }

  // ---------- Views ----------

  showController(): void {
    this.flushBody();
    this.view = 'controller';
    this.opened = null;
    this.bodyWs?.highlightBlock(null);
    this.session.setFocus(this.selectedFunctionRef());
    this.renderBars();
    this.resize();
  }

  /** Opens a function block's body (blocks or text). */
  openBlock(blockId: string): void {
    this.ensureWorkspaces();
    if (this.reloadPending) this.reload();
    const block = this.ctrlWs!.getBlockById(blockId);
    if (!block || block.type !== CONTROLLER_FUNCTION_BLOCK) return;
    this.flushBody();
    this.ensureBody(block);
    if (this.opened?.blockId === blockId && this.view === 'function') {
      this.opened.ref = refOf(block);
      return;
    }
    this.opened = { blockId, ref: refOf(block), broken: false };
    this.view = 'function';
    this.bodyNote = null;
    this.runNote = null;
    const body = functionExtra(block).body!;
    if (body.kind === 'text') this.text.setCode(body.code);
    else this.loadBodyWorkspace(block, body.blocks);
    this.applyOpenedLock();
    this.session.setFocus(this.opened.ref);
    this.runErrorChanged(this.session.error);
    this.renderBars();
    this.resize();
    if (body.kind === 'blocks') scrollToStart(this.bodyWs!);
    this.checkBody();
  }

  /** Opens a function by name (the diagram's click on a function, the Errors panel). */
  openFunction(layer: string, fn: string): boolean {
    return this.openRef({ layer, fn });
  }

  openRef(ref: FunctionRef): boolean {
    this.ensureWorkspaces();
    if (this.reloadPending) this.reload();
    const block = this.functionBlock(ref);
    if (!block) return false;
    this.openBlock(block.id);
    return true;
  }

  private loadBodyWorkspace(block: Blockly.Block, blocks: JsonValue): void {
    const ws = this.bodyWs!;
    Blockly.Events.disable();
    try {
      ws.clear();
      // The names first: the blocks' dropdowns read them as they are created.
      const context = contextFromBlock(block);
      setFunctionContext(ws, context);
      loadBody(ws, blocks, context);
    } catch (e) {
      this.opened!.broken = true;
      this.bodyNote = { kind: 'error', text: `${e instanceof Error ? e.message : String(e)} The blocks are kept as they are in the file; nothing here is saved over them.` };
    } finally {
      Blockly.Events.enable();
    }
    ws.clearUndo();
  }

  private selectedFunctionRef(): FunctionRef | null {
    const selected = Blockly.getSelected();
    const block = selected instanceof Blockly.BlockSvg && selected.workspace === this.ctrlWs ? functionBlockOf(selected) : null;
    return block ? refOf(block) : null;
  }

  private functionBlock(ref: FunctionRef): Blockly.Block | null {
    const blocks = this.ctrlWs?.getBlocksByType(CONTROLLER_FUNCTION_BLOCK, false) ?? [];
    return blocks.find((b) => nameOf(b) === ref.fn && refOf(b).layer === ref.layer) ?? blocks.find((b) => nameOf(b) === ref.fn) ?? null;
  }

  private renderBars(): void {
    const fnView = this.view === 'function' && !!this.opened;
    this.root.dataset.view = fnView ? 'function' : 'controller';
    this.ctrlDiv.classList.toggle('lbe-off', fnView);
    const block = fnView ? this.ctrlWs?.getBlockById(this.opened!.blockId) : null;
    const textMode = !!block && functionExtra(block).body?.kind === 'text';
    this.bodyDiv.classList.toggle('lbe-off', !fnView || textMode);
    this.text.element.classList.toggle('lbe-off', !fnView || !textMode);
    this.ctrlBar.hidden = fnView;
    this.fnBar.hidden = !fnView;

    // Breadcrumb: Controller › Layer › function.
    this.crumbs.replaceChildren();
    const spec = this.session.spec;
    const home = el('button', 'lbe-crumb', 'Controller');
    home.type = 'button';
    home.dataset.crumb = 'controller';
    home.title = spec ? `Back to the layers of “${spec.name}”` : 'The controller';
    home.disabled = !fnView;
    home.addEventListener('click', () => this.showController());
    this.crumbs.appendChild(home);
    if (fnView) {
      const ref = this.opened!.ref;
      this.crumbs.append(el('span', 'lbe-crumb-sep', '›'), el('span', 'lbe-crumb-part', ref.layer || '(no layer)'), el('span', 'lbe-crumb-sep', '›'));
      const fn = el('span', 'lbe-crumb-part lbe-crumb-current', ref.fn);
      fn.dataset.crumb = 'function';
      this.crumbs.appendChild(fn);
      if (spec?.bodyCommand === ref.fn) this.crumbs.appendChild(el('span', 'lbe-tag', 'body command'));
    } else if (spec) {
      this.crumbs.appendChild(el('span', 'lbe-crumb-name', spec.name));
    }

    const locked = fnView && isFunctionLocked(this.session.restrictions, this.opened!.ref.layer, this.opened!.ref.fn);
    this.lockBadge.hidden = !locked;
    this.modeBlocks.setAttribute('aria-pressed', String(!textMode));
    this.modeText.setAttribute('aria-pressed', String(textMode));
    this.modeBlocks.disabled = locked;
    this.modeText.disabled = locked;
    this.text.setReadOnly(locked);
    if (fnView && block) this.text.setFrame(specsFromBlock(block).fn, specsFromBlock(block).layer);

    this.renderJump();
    this.renderUndo();
    this.renderBanner();
  }

  private renderJump(): void {
    const spec = this.session.spec;
    this.jump.replaceChildren();
    const first = el('option', '', 'Function…');
    first.value = '';
    this.jump.append(first, ...functionOptionGroups(spec));
    this.jump.value = '';
    this.jump.disabled = !spec;
  }

  private renderUndo(): void {
    const ws = this.activeWorkspace();
    this.undoBtn.disabled = !ws || ws.getUndoStack().length === 0;
    this.redoBtn.disabled = !ws || ws.getRedoStack().length === 0;
  }

  private renderBanner(): void {
    const notes: { text: string; kind: string }[] = [];
    if (this.view === 'controller' && this.session.problem) notes.push({ text: this.session.problem, kind: 'error' });
    if (this.view === 'function') {
      if (this.runNote) notes.push({ text: this.runNote, kind: 'error' });
      if (this.bodyNote) notes.push(this.bodyNote);
    }
    this.banner.replaceChildren(...notes.map((n) => el('div', `lbe-note ${n.kind}`, n.text)));
    this.banner.hidden = notes.length === 0;
  }

  private activeWorkspace(): Blockly.WorkspaceSvg | null {
    if (this.view === 'controller') return this.ctrlWs;
    const block = this.opened ? this.ctrlWs?.getBlockById(this.opened.blockId) : null;
    return block && functionExtra(block).body?.kind !== 'text' ? this.bodyWs : null;
  }

  private undo(redo: boolean): void {
    const ws = this.activeWorkspace();
    if (!ws) return;
    ws.undo(redo);
    this.renderUndo();
  }

  // ---------- Controller workspace events ----------

  private controllerEvent(e: Blockly.Events.Abstract): void {
    if (e.isUiEvent) {
      if (e.type === Blockly.Events.SELECTED && this.view === 'controller') this.session.setFocus(this.selectedFunctionRef());
      if (e.type === Blockly.Events.CLICK) this.clicked(e as Blockly.Events.Click);
      return;
    }
    if (e.type === Blockly.Events.BLOCK_CREATE) this.created(e as Blockly.Events.BlockCreate);
    if (e.type === Blockly.Events.BLOCK_CHANGE) this.changed(e as Blockly.Events.BlockChange);
    this.scheduleSync();
    this.renderUndo();
  }

  private clicked(e: Blockly.Events.Click): void {
    if (e.targetType !== 'block' || !e.blockId) return;
    const block = this.ctrlWs?.getBlockById(e.blockId);
    const now = performance.now();
    const double = this.lastClick.id === e.blockId && now - this.lastClick.at < DOUBLE_CLICK_MS;
    this.lastClick = { id: e.blockId, at: now };
    if (double && block?.type === CONTROLLER_FUNCTION_BLOCK) this.openBlock(block.id);
  }

  /** New blocks get names of their own and a function block its empty body. */
  private created(e: Blockly.Events.BlockCreate): void {
    const ws = this.ctrlWs!;
    const group = Blockly.Events.getGroup();
    Blockly.Events.setGroup(e.group || true);
    try {
      for (const id of e.ids ?? []) {
        const block = ws.getBlockById(id);
        if (!block) continue;
        const others = (type: string) => ws.getBlocksByType(type, false).filter((b) => b !== block).map(nameOf);
        if (block.type === CONTROLLER_FUNCTION_BLOCK) {
          const name = uniqueName(nameOf(block), others(CONTROLLER_FUNCTION_BLOCK));
          if (name !== nameOf(block)) block.setFieldValue(name, 'NAME');
          this.ensureBody(block);
          this.decorate(block);
        } else if (block.type === LAYER_BLOCK) {
          const name = uniqueName(nameOf(block), others(LAYER_BLOCK), true);
          if (name !== nameOf(block)) block.setFieldValue(name, 'NAME');
        } else if (block.type === RANDOM_SOURCE_BLOCK) {
          const name = uniqueName(nameOf(block), others(RANDOM_SOURCE_BLOCK));
          if (name !== nameOf(block)) block.setFieldValue(name, 'NAME');
        }
      }
    } finally {
      Blockly.Events.setGroup(group);
    }
  }

  /** Renaming a function or a random source renames the arcs that read it (in the same undo step). */
  private changed(e: Blockly.Events.BlockChange): void {
    if (e.element !== 'field' || e.name !== 'NAME' || !e.blockId) return;
    const ws = this.ctrlWs!;
    const block = ws.getBlockById(e.blockId);
    if (!block) return;
    const from = String(e.oldValue ?? '');
    const to = String(e.newValue ?? '');
    const kind = block.type === CONTROLLER_FUNCTION_BLOCK ? 'function' : block.type === RANDOM_SOURCE_BLOCK ? 'random' : null;
    if (kind && from && to) {
      const group = Blockly.Events.getGroup();
      Blockly.Events.setGroup(e.group || true);
      try {
        for (const arc of ws.getBlocksByType(ARC_BLOCK, false)) {
          const source = String(arc.getFieldValue('SOURCE') ?? '');
          const next = renamedSource(source, kind, from, to);
          if (next !== source) arc.setFieldValue(next, 'SOURCE');
        }
      } finally {
        Blockly.Events.setGroup(group);
      }
      const spec = this.session.spec;
      if (kind === 'function' && spec && spec.bodyCommand === from) this.session.spec = { ...spec, bodyCommand: to };
    }
    if (this.opened) {
      const openBlock = ws.getBlockById(this.opened.blockId);
      if (openBlock) this.opened.ref = refOf(openBlock);
    }
  }

  private ensureBody(block: Blockly.Block): void {
    const extra = functionExtra(block);
    if (!extra.body || (extra.body.kind === 'blocks' && (extra.body.blocks === null || extra.body.blocks === undefined))) {
      setFunctionExtra(block, { ...extra, body: { kind: 'blocks', blocks: emptyBody() } });
    }
  }

  private scheduleSync(): void {
    if (this.syncTimer) clearTimeout(this.syncTimer);
    this.syncTimer = setTimeout(() => {
      this.syncTimer = null;
      if (this.ctrlWs?.isDragging()) return this.scheduleSync();
      this.sync();
    }, SYNC_DELAY_MS);
  }

  /** Reads the controller back from the workspace and hands it to the session. */
  private sync(base = this.session.spec): void {
    const ws = this.ctrlWs;
    const before = this.session.spec;
    if (!ws || !base || !before) return;
    for (const block of ws.getBlocksByType(CONTROLLER_FUNCTION_BLOCK, false)) this.ensureBody(block);
    let next: ControllerSpec;
    try {
      next = workspaceToController(ws, base);
    } catch (e) {
      this.session.setProblem(e instanceof Error ? e.message : String(e));
      return;
    }
    const violation = this.baseline ? lockViolation(this.baseline, next, this.session.restrictions) : null;
    if (violation) {
      this.host.notice(violation, 'error');
      ws.undo(false);
      return;
    }
    const problems = validateController(next);
    this.session.setProblem(problems.length ? problems[0].message + (problems.length > 1 ? ` (and ${problems.length - 1} more)` : '') : null);
    if (JSON.stringify(next) !== JSON.stringify(before)) this.session.setSpec(next, 'blocks');
    this.decorateAll();
    this.renderBars();
  }

  // ---------- Body workspace ----------

  private bodyEvent(e: Blockly.Events.Abstract): void {
    if (e.isUiEvent || !this.opened || this.opened.broken) return;
    if (this.bodyTimer) clearTimeout(this.bodyTimer);
    this.bodyTimer = setTimeout(() => {
      this.bodyTimer = null;
      if (this.bodyWs?.isDragging()) return this.bodyEvent(e);
      this.saveBody();
    }, SYNC_DELAY_MS);
    this.renderUndo();
  }

  private flushBody(): void {
    if (!this.bodyTimer) return;
    clearTimeout(this.bodyTimer);
    this.bodyTimer = null;
    this.saveBody();
  }

  /** Copies the body workspace into the function block, then reads the controller back. */
  private saveBody(): void {
    const opened = this.opened;
    const block = opened ? this.ctrlWs?.getBlockById(opened.blockId) : null;
    if (!opened || !block || opened.broken || !this.bodyWs || functionExtra(block).body?.kind === 'text') return;
    const blocks = JSON.parse(JSON.stringify(Blockly.serialization.workspaces.save(this.bodyWs))) as JsonValue;
    setFunctionExtra(block, { ...functionExtra(block), body: { kind: 'blocks', blocks } });
    this.checkBody();
    this.sync();
  }

  /** Says plainly when the open function's blocks cannot become code (they are kept). */
  private checkBody(): void {
    const block = this.opened ? this.ctrlWs?.getBlockById(this.opened.blockId) : null;
    if (!block || this.opened!.broken) return this.renderBanner();
    const { fn, layer } = specsFromBlock(block);
    this.bodyNote = null;
    if (fn.body.kind === 'blocks') {
      try {
        generateBody(fn, layer);
      } catch (e) {
        this.bodyNote = { kind: 'warn', text: `Not runnable yet: ${e instanceof Error ? e.message : String(e)} Your blocks are kept.` };
      }
    }
    this.renderBanner();
  }

  private textEdited(code: string): void {
    const block = this.opened ? this.ctrlWs?.getBlockById(this.opened.blockId) : null;
    if (!block) return;
    setFunctionExtra(block, { ...functionExtra(block), body: { kind: 'text', code } });
    this.scheduleSync();
  }

  // ---------- Text mode ----------

  private async switchMode(mode: 'blocks' | 'text'): Promise<void> {
    const opened = this.opened;
    const block = opened ? this.ctrlWs?.getBlockById(opened.blockId) : null;
    if (!opened || !block) return;
    const body = functionExtra(block).body;
    if (!body || body.kind === mode) return;
    if (isFunctionLocked(this.session.restrictions, opened.ref.layer, opened.ref.fn)) return;
    if (mode === 'text') {
      this.flushBody();
      const { fn, layer } = specsFromBlock(block);
      const result = textBodyOf(fn, layer, generateBody);
      if ('error' in result) {
        await alertDialog('These blocks cannot become JavaScript yet', `${result.error}\n\nFix the blocks first, then switch to JavaScript.`);
        return;
      }
      if (body.kind === 'blocks') this.blocksBeforeText.set(opened.blockId, body.blocks);
      setFunctionExtra(block, { ...functionExtra(block), body: result.body });
      if (result.body.kind === 'text') this.text.setCode(result.body.code);
    } else {
      const before = this.blocksBeforeText.get(opened.blockId);
      const ok = await confirmDialog(
        'Switch back to blocks?',
        `JavaScript text cannot be turned into blocks: the text of “${opened.ref.fn}” will be lost. ` +
          (before !== undefined ? 'The function gets back the blocks it had before you switched to JavaScript.' : 'The function starts again from an empty function block.'),
        'Switch to blocks',
        true,
      );
      if (!ok || this.opened !== opened) return;
      const blocks = before ?? emptyBody();
      this.blocksBeforeText.delete(opened.blockId);
      setFunctionExtra(block, { ...functionExtra(block), body: { kind: 'blocks', blocks } });
      this.loadBodyWorkspace(block, blocks);
    }
    this.decorate(block);
    this.sync();
    this.checkBody();
    this.renderBars();
    this.resize();
  }

  // ---------- Locks and badges ----------

  private toolboxCategories(): string[] | undefined {
    const t = this.session.restrictions?.toolbox;
    return t ? [...t] : undefined;
  }

  private applyRestrictions(): void {
    if (!this.ctrlWs) return;
    const r = this.session.restrictions;
    // The locks are checked against the controller as it is now.
    this.baseline = this.session.spec;
    for (const layerBlock of this.ctrlWs.getBlocksByType(LAYER_BLOCK, false)) {
      const layer = nameOf(layerBlock);
      const whole = isLayerLocked(r, layer);
      this.lock(layerBlock, whole, false);
      for (const child of [...statementChildren(layerBlock, 'VARIABLES'), ...statementChildren(layerBlock, 'RANDOM')]) this.lock(child, whole, true);
      for (const fnBlock of statementChildren(layerBlock, 'FUNCTIONS')) {
        const locked = isFunctionLocked(r, layer, nameOf(fnBlock));
        this.lock(fnBlock, locked, false);
        for (const arc of fnBlock.getDescendants(false)) if (arc !== fnBlock) this.lock(arc, locked, true);
      }
    }
    try {
      this.bodyWs?.updateToolbox(makeToolbox(this.toolboxCategories()));
    } catch (e) {
      this.host.notice(`The challenge's toolbox could not be set: ${e instanceof Error ? e.message : String(e)}`, 'error');
    }
    this.applyOpenedLock();
    this.renderBars();
  }

  private lock(block: Blockly.Block, locked: boolean, quiet: boolean): void {
    block.setEditable(!locked);
    block.setDeletable(!locked);
    block.setMovable(!locked);
    if (!quiet) this.setBadge(block, LOCK_FIELD, locked ? LOCK_BADGE : null, 'Locked in this challenge');
  }

  private applyOpenedLock(): void {
    const ws = this.bodyWs;
    if (!ws) return;
    const locked = !!this.opened && isFunctionLocked(this.session.restrictions, this.opened.ref.layer, this.opened.ref.fn);
    ws.setIsReadOnly(locked);
    for (const b of ws.getAllBlocks(false)) {
      b.setEditable(!locked);
      b.setDeletable(!locked);
      b.setMovable(!locked);
    }
    ws.getToolbox()?.setVisible(!locked);
    this.root.classList.toggle('lbe-locked', locked);
  }

  private decorateAll(): void {
    for (const b of this.ctrlWs?.getBlocksByType(CONTROLLER_FUNCTION_BLOCK, false) ?? []) this.decorate(b);
    // Arc sources name functions anywhere in the controller: relabel them once all are known.
    for (const arc of this.ctrlWs?.getBlocksByType(ARC_BLOCK, false) ?? []) {
      const field = arc.getField('SOURCE');
      if (field instanceof FieldNameDropdown) field.refresh();
    }
  }

  /** The "JS" badge on text-mode functions. */
  private decorate(block: Blockly.Block): void {
    const text = functionExtra(block).body?.kind === 'text';
    this.setBadge(block, TEXT_FIELD, text ? TEXT_BADGE : null, 'Written as JavaScript text', 22);
  }

  private setBadge(block: Blockly.Block, name: string, src: string | null, tooltip: string, width = 16): void {
    const input = block.inputList[0];
    if (!input) return;
    const has = !!block.getField(name);
    if (!src) {
      if (has) input.removeField(name, true);
      return;
    }
    if (has) return;
    const field = new Blockly.FieldImage(src, width, 16, tooltip);
    field.setTooltip(tooltip);
    // Badges go first in the row, after the "open" button.
    input.insertFieldAt(input.fieldRow.findIndex((f) => f.name === OPEN_FIELD) + 1, field, name);
  }

  // ---------- Adding layers ----------

  private lastLayerBlock(): Blockly.Block | null {
    const ws = this.ctrlWs!;
    const top = ws.getTopBlocks(true).find((b) => b.type === LAYER_BLOCK);
    let last: Blockly.Block | null = top ?? null;
    while (last?.getNextBlock()) last = last.getNextBlock();
    return last;
  }

  /** Adds a layer state at the bottom of the stack (one undo step) and shows it. */
  private appendLayer(state: Blockly.serialization.blocks.State): Blockly.BlockSvg | null {
    const ws = this.ctrlWs!;
    const last = this.lastLayerBlock();
    Blockly.Events.setGroup(true);
    let block: Blockly.BlockSvg | null = null;
    try {
      block = Blockly.serialization.blocks.append(state, ws, { recordUndo: true }) as Blockly.BlockSvg;
      if (last?.nextConnection && block.previousConnection) last.nextConnection.connect(block.previousConnection);
      else block.moveBy(20, 20);
    } finally {
      Blockly.Events.setGroup(false);
    }
    this.applyRestrictions();
    this.decorateAll();
    ws.centerOnBlock(block.id, true);
    block.select();
    return block;
  }

  private addLayer(): void {
    if (!this.session.spec) return;
    this.ensureWorkspaces();
    this.appendLayer({ type: LAYER_BLOCK, fields: { NAME: 'Layer' } });
  }

  private async copyLayerFromFile(): Promise<void> {
    const file = this.fileInput.files?.[0];
    this.fileInput.value = '';
    const spec = this.session.spec;
    if (!file || !spec) return;
    const parsed = parseController(await file.text(), file.name);
    if (!parsed.ok) {
      await alertDialog(`“${file.name}” is not a controller Layerbot can read`, formatProblems(parsed.problems.slice(0, 5)));
      return;
    }
    const other = parsed.value;
    if (other.layers.length === 0) {
      await alertDialog('No layers to copy', `“${file.name}” has no layers.`);
      return;
    }
    const layer = await chooseDialog(
      'Copy a layer',
      `Choose a layer of “${other.name}” to add at the bottom of your controller.`,
      other.layers.map((l) => ({
        value: l,
        title: l.name,
        detail: [`${l.functions.length} function${l.functions.length === 1 ? '' : 's'}: ${l.functions.map((f) => f.name).join(', ') || 'none'}`, ...l.variables.map((v) => `${v.name} = ${JSON.stringify(v.value)}`)].join(' · '),
      })),
    );
    if (!layer) return;
    this.flushBody();
    const copy = copyLayerInto(this.session.spec ?? spec, layer);
    this.appendLayer(layerState(copy.layer));
    // The copy's base knows the new layer's description (it has no block).
    this.sync(copy.spec);
    const renamed = copy.renamed.length ? ` Renamed to avoid a clash: ${copy.renamed.join(', ')}.` : '';
    const missing = copy.missing.length ? ` It reads functions this controller lacks: ${copy.missing.join(', ')}.` : '';
    this.host.notice(`Added the layer “${copy.layer.name}” from ${file.name}.${renamed}${missing}`, copy.missing.length ? 'error' : 'info');
  }

  // ---------- Errors, stepping ----------

  stepInto(ref: FunctionRef): void {
    this.flushBody();
    this.session.flush();
    this.host.stepInto(ref.layer, ref.fn);
  }

  private runErrorChanged(e: ControllerError | null): void {
    const opened = this.opened;
    this.runNote = e && opened && e.function === opened.ref.fn ? `Tick ${e.tick}: ${e.message}` : null;
    this.renderBanner();
  }

  revealError(error: ControllerError): boolean {
    if (!error.function) return false;
    const layer = error.layer ?? '';
    if (!this.openRef({ layer, fn: error.function })) return false;
    this.runErrorChanged(error);
    const block = error.blockId ? this.bodyWs?.getBlockById(error.blockId) : null;
    if (block) {
      block.select();
      // After the pane is on view (PaneArea shows it next), bring the block to the middle.
      requestAnimationFrame(() => {
        this.resize();
        this.bodyWs?.centerOnBlock(block.id, true);
      });
    }
    return true;
  }

  highlightStep(point: StepPoint | null): boolean {
    if (!point) {
      this.bodyWs?.highlightBlock(null);
      return !!this.bodyWs;
    }
    if (!this.openRef({ layer: point.layer, fn: point.function })) return false;
    const ws = this.bodyWs!;
    ws.highlightBlock(null);
    if (point.blockId && ws.getBlockById(point.blockId)) {
      ws.highlightBlock(point.blockId);
      const id = point.blockId;
      requestAnimationFrame(() => ws.getBlockById(id) && ws.scrollBoundsIntoView((ws.getBlockById(id) as Blockly.BlockSvg).getBoundingRectangleWithoutChildren()));
    }
    return true;
  }

  private cancelTimers(): void {
    if (this.syncTimer) clearTimeout(this.syncTimer);
    if (this.bodyTimer) clearTimeout(this.bodyTimer);
    this.syncTimer = null;
    this.bodyTimer = null;
  }

  /** For the browser tests: what the pane shows. */
  testState(): { view: View; opened: FunctionRef | null; mode: 'blocks' | 'text' | null; readOnly: boolean; layers: string[]; toolbox: string[]; problem: string | null; note: string | null } {
    const block = this.opened ? this.ctrlWs?.getBlockById(this.opened.blockId) : null;
    const toolbox = (this.bodyWs?.getToolbox() as Blockly.Toolbox | null)?.getToolboxItems().map((i) => (i as Blockly.ToolboxCategory).getName?.() ?? '') ?? [];
    return {
      view: this.view,
      opened: this.opened ? { ...this.opened.ref } : null,
      mode: block ? (functionExtra(block).body?.kind ?? null) : null,
      readOnly: !!this.bodyWs?.isReadOnly(),
      layers: this.ctrlWs?.getBlocksByType(LAYER_BLOCK, true).map(nameOf) ?? [],
      toolbox,
      problem: this.session.problem,
      note: this.bodyNote?.text ?? null,
    };
  }

  /** For the browser tests: the controller workspace's block for a function. */
  testFunctionBlockId(ref: FunctionRef): string | null {
    return this.functionBlock(ref)?.id ?? null;
  }
}
