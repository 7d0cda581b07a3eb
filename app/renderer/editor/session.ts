/**
 * What the Blocks and Code panes share: the controller being edited, the function on view, the
 * challenge restrictions and the last run error. Edits reach the app through `host.updateController`
 * a moment after the last change (the app reloads the engine each time), or at once on `flush()`.
 */
import type { ControllerSpec, FunctionBody } from '../../core/controller/model';
import type { ControllerError } from '../../core/session/types';
import { Emitter } from '../app/emitter';
import type { EditRestrictions, PaneHost } from '../panes/types';
import type { FunctionRef } from './model';
import { withBody } from './model';

/** Who changed the controller: a pane of the editor, or the app (a file was opened). */
export type SpecOrigin = 'blocks' | 'code' | 'host';

const PUSH_DELAY_MS = 250;

export class EditorSession {
  host: PaneHost | null = null;
  spec: ControllerSpec | null = null;
  /** The function on view: open in the Blocks pane, or selected there. */
  focus: FunctionRef | null = null;
  restrictions: EditRestrictions | null = null;
  error: ControllerError | null = null;
  /** A problem that keeps the Blocks pane's workspace from becoming a controller (shown, not pushed). */
  problem: string | null = null;
  readonly onSpec = new Emitter<SpecOrigin>();
  readonly onFocus = new Emitter<FunctionRef | null>();
  readonly onRestrictions = new Emitter<EditRestrictions | null>();
  readonly onError = new Emitter<ControllerError | null>();
  readonly onProblem = new Emitter<string | null>();
  private timer: ReturnType<typeof setTimeout> | null = null;
  private sent: ControllerSpec | null = null;

  /** Connects to the app (both panes call it; the first call counts). */
  attach(host: PaneHost): void {
    if (this.host) return;
    this.host = host;
    this.spec = host.controller();
    this.restrictions = host.restrictions();
    host.onControllerOpened((spec) => {
      // The app also announces the controller it got from us: that is no new document.
      if (spec === this.sent || spec === this.spec) return;
      this.cancel();
      this.spec = spec;
      this.setProblem(null);
      this.onSpec.emit('host');
    });
    host.onRestrictionsChanged((r) => {
      this.restrictions = r;
      this.onRestrictions.emit(r);
    });
    host.onError((e) => {
      this.error = e;
      this.onError.emit(e);
    });
  }

  /** An edit from a pane: shown at once in the other pane, sent to the app shortly. */
  setSpec(spec: ControllerSpec, origin: SpecOrigin): void {
    this.spec = spec;
    this.onSpec.emit(origin);
    this.cancel();
    this.timer = setTimeout(() => this.flush(), PUSH_DELAY_MS);
  }

  setBody(ref: FunctionRef, body: FunctionBody, origin: SpecOrigin): void {
    if (this.spec) this.setSpec(withBody(this.spec, ref, body), origin);
  }

  /** Sends a pending edit to the app now (before Run, Step into, leaving the pane). */
  flush(): void {
    if (!this.timer) return;
    this.cancel();
    if (this.spec && this.host) {
      this.sent = this.spec;
      this.host.updateController(this.spec);
    }
  }

  get pending(): boolean {
    return this.timer !== null;
  }

  setFocus(ref: FunctionRef | null): void {
    if (ref?.layer === this.focus?.layer && ref?.fn === this.focus?.fn) return;
    this.focus = ref;
    this.onFocus.emit(ref);
  }

  setProblem(problem: string | null): void {
    if (problem === this.problem) return;
    this.problem = problem;
    this.onProblem.emit(problem);
  }

  private cancel(): void {
    if (this.timer) clearTimeout(this.timer);
    this.timer = null;
  }
}
