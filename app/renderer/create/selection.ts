/** The Create mode's selection and tool, shared by the pointer handler, the inspector and the keys. */
import { Emitter } from '../app/emitter';

export type Tool = 'select' | 'wall' | 'goal' | 'robot' | 'delete';

export type Selection =
  | { readonly kind: 'robot' }
  | { readonly kind: 'goal'; readonly name: string }
  | { readonly kind: 'wall'; readonly index: number }
  | null;

export class CreateState {
  tool: Tool = 'select';
  selection: Selection = null;
  snap = true;
  snapStep = 1;
  readonly onChange = new Emitter<void>();
  /** Asks the inspector to focus the selected goal's name (right after placing it). */
  readonly onNameGoal = new Emitter<string>();

  setTool(tool: Tool): void {
    this.tool = tool;
    this.onChange.emit();
  }

  select(s: Selection): void {
    this.selection = s;
    this.onChange.emit();
  }

  setSnap(on: boolean, step = this.snapStep): void {
    this.snap = on;
    this.snapStep = step > 0 ? step : 1;
    this.onChange.emit();
  }

  /** Rounds a world coordinate to the snap grid when snapping is on. */
  snapValue(v: number): number {
    if (!this.snap) return Math.round(v * 100) / 100;
    return Math.round(v / this.snapStep) * this.snapStep;
  }
}
