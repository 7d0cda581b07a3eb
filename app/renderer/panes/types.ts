/**
 * The mount interface of the right-hand pane ("Blocks | Diagram | Code"). The controller editor
 * (app/renderer/editor/) and the diagram (app/renderer/diagram/) implement `ControllerPane`; the
 * app gives each a `PaneHost` to read the controller and the run, and to report edits.
 * See app/renderer/CONTEXT.md.
 */
import type { ControllerSpec } from '../../core/controller/model';
import type { Lock, ToolboxCategory } from '../../core/packs/model';
import type { ControllerError } from '../../core/session/types';
import type { ArcRow } from '../engine/client';
import type { FunctionInfo } from '../engine/protocol';

export type Unsubscribe = () => void;

/** What the app offers a pane. */
export interface PaneHost {
  /** The controller being edited, or null when none is open. */
  controller(): ControllerSpec | null;
  /**
   * The user changed the controller in this pane. The app stores it, autosaves it, and loads it
   * into the engine at the next Step, Run or Reset. Keep undo and redo inside the editor.
   */
  updateController(spec: ControllerSpec): void;
  /** A different controller was opened (a file, an example, a restore); not called for `updateController`. */
  onControllerOpened(fn: (spec: ControllerSpec | null) => void): Unsubscribe;
  /** The tick on view in the timeline, and its changes (scrubbing, running). */
  selectedTick(): number;
  onTickSelected(fn: (tick: number) => void): Unsubscribe;
  /** Every arc's value at a tick (empty when no controller runs). */
  arcs(tick: number): Promise<readonly ArcRow[]>;
  /** The functions the engine runs, with their layers (empty before a controller loads). */
  functions(): readonly FunctionInfo[];
  /** The error that stopped the run, when there is one at or before the selected tick. */
  onError(fn: (error: ControllerError | null) => void): Unsubscribe;
  /** Shows a message in the status line. */
  notice(text: string, kind?: 'info' | 'error'): void;
  /** Brings a pane to the front by id. */
  showPane(id: string): void;
  /**
   * What the open challenge restricts (locked layers and functions, the toolbox categories on
   * offer), or null when no challenge is open: everything is editable, every category offered.
   */
  restrictions(): EditRestrictions | null;
  onRestrictionsChanged(fn: (r: EditRestrictions | null) => void): Unsubscribe;
  /** Replays a function at the selected tick in the step-by-step debugger (block by block). */
  stepInto(layer: string, fn: string): void;
  /**
   * Asks the panes to open a function for editing (the diagram's click on an oval): each pane's
   * `openFunction` is called; the first that returns true comes to the front. False when none did.
   */
  openFunction(layer: string, fn: string): boolean;
}

/** A challenge's limits on editing, as the controller editor applies them. */
export interface EditRestrictions {
  /** Locked layers (no `function`) and single functions: visible, not editable. */
  readonly locked: readonly Lock[];
  /** The body toolbox categories offered; absent means all of them. */
  readonly toolbox?: readonly ToolboxCategory[];
}

/** Where the step-by-step debugger is: the block about to run in a function, or nothing. */
export interface StepPoint {
  readonly layer: string;
  readonly function: string;
  /** The block about to run; null when the function has not started or has returned. */
  readonly blockId: string | null;
}

/** A tab of the right-hand pane. */
export interface ControllerPane {
  /** Stable id: 'blocks', 'diagram', 'code'. */
  readonly id: string;
  readonly title: string;
  /** Called once, with the pane's own element (absolutely filling the pane body). */
  mount(element: HTMLElement, host: PaneHost): void;
  /** The tab became visible (Blockly needs `svgResize` here) or hidden. */
  shown?(): void;
  hidden?(): void;
  /**
   * Takes the user to the block that caused an error (the Errors panel's "Show block" button).
   * Returns true when this pane handled it; the app then brings the pane to the front.
   */
  revealError?(error: ControllerError): boolean;
  /**
   * Shows where the debugger is (opens the function, highlights the block); null clears the
   * highlight. Returns true when this pane shows it.
   */
  highlightStep?(point: StepPoint | null): boolean;
  /**
   * Opens a function (the Blocks pane shows its blocks). Returns true when this pane shows it; the
   * app then brings the pane to the front. Panes that only mark the function return false.
   */
  openFunction?(layer: string, fn: string): boolean;
}
