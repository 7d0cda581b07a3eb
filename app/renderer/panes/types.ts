/**
 * The mount interface of the right-hand pane ("Blocks | Diagram | Code"). The controller editor
 * (app/renderer/editor/) and the diagram (app/renderer/diagram/) implement `ControllerPane`; the
 * app gives each a `PaneHost` to read the controller and the run, and to report edits.
 * See app/renderer/CONTEXT.md.
 */
import type { ControllerSpec } from '../../core/controller/model';
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
}
