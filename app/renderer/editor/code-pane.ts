/**
 * The Code pane: the JavaScript of one function as the engine runs it (generated from its blocks,
 * read-only), or the editable text of a text-mode function. It follows the function on view in
 * the Blocks pane; the picker at the top shows any other.
 */
import { generateBody } from '../../../blocks/generate';
import { el } from '../panels/dom';
import { functionOptionGroups, functionValue } from './pickers';
import type { ControllerPane, PaneHost } from '../panes/types';
import { tokenize } from './highlight';
import type { FunctionRef } from './model';
import { findFunction, functionCode, isFunctionLocked } from './model';
import type { EditorSession } from './session';
import { expandButton, TextEditor } from './text-editor';

export class CodePane implements ControllerPane {
  readonly id = 'code';
  readonly title = 'Code';
  private root!: HTMLElement;
  private picker!: HTMLSelectElement;
  private meta!: HTMLElement;
  private body!: HTMLElement;
  private readonly text = new TextEditor();
  private chosen: FunctionRef | null = null;
  private visible = false;
  private dirty = true;

  constructor(private readonly session: EditorSession) {}

  mount(element: HTMLElement, host: PaneHost): void {
    this.session.attach(host);
    this.root = el('div', 'lbe lbe-codepane');
    const bar = el('div', 'lbe-bar');
    this.picker = el('select', 'lbe-select lbe-picker');
    this.picker.setAttribute('aria-label', 'Function');
    this.picker.addEventListener('change', () => {
      const [layer, fn] = this.picker.value.split('\u0000');
      if (fn !== undefined) this.chosen = { layer, fn };
      this.render();
    });
    const tools = el('div', 'lbe-bar-tools');
    tools.append(expandButton());
    bar.append(this.picker, tools);
    this.meta = el('div', 'lbe-meta');
    this.body = el('div', 'lbe-code-body');
    this.root.append(bar, this.meta, this.body);
    element.appendChild(this.root);
    this.text.onEdit = (code) => {
      const ref = this.current();
      if (ref) this.session.setBody(ref, { kind: 'text', code }, 'code');
    };
    this.session.onSpec.on((origin) => {
      if (origin === 'host') this.chosen = null;
      this.invalidate();
    });
    this.session.onFocus.on((ref) => {
      if (ref) this.chosen = ref;
      this.invalidate();
    });
    this.session.onRestrictions.on(() => this.invalidate());
    this.render();
  }

  shown(): void {
    this.visible = true;
    if (this.dirty) this.render();
  }

  hidden(): void {
    this.visible = false;
    this.session.flush();
  }

  private invalidate(): void {
    this.dirty = true;
    if (this.visible) this.render();
  }

  /** The function on view: the chosen one if it still exists, else the first. */
  private current(): FunctionRef | null {
    const spec = this.session.spec;
    if (!spec) return null;
    if (findFunction(spec, this.chosen)) return this.chosen;
    const layer = spec.layers.find((l) => l.functions.length);
    return layer ? { layer: layer.name, fn: layer.functions[0].name } : null;
  }

  private render(): void {
    this.dirty = false;
    const spec = this.session.spec;
    const ref = this.current();
    this.picker.replaceChildren(...functionOptionGroups(spec));
    this.picker.disabled = !spec;
    if (ref) this.picker.value = functionValue(ref);

    const found = findFunction(spec, ref);
    if (!found) {
      this.meta.replaceChildren();
      const empty = el('div', 'lbe-empty');
      empty.append(el('strong', '', spec ? 'No functions yet' : 'No controller is open'), el('span', '', spec ? 'Add a function to a layer in the Blocks pane.' : 'Open one from File › Example controllers.'));
      this.body.replaceChildren(empty);
      return;
    }
    const { fn, layer } = found;
    const code = functionCode(fn, layer, generateBody);
    const locked = isFunctionLocked(this.session.restrictions, layer.name, fn.name);
    const tags = [el('span', 'lbe-tag', `layer ${layer.name}`), el('span', 'lbe-tag', `gives ${fn.output}`)];
    if (spec?.bodyCommand === fn.name) tags.push(el('span', 'lbe-tag', 'body command'));
    tags.push(el('span', `lbe-tag ${code.kind === 'text' ? 'accent' : ''}`, code.kind === 'text' ? 'JavaScript text · editable' : 'generated from blocks · read-only'));
    if (locked) tags.push(el('span', 'lbe-tag lock', 'locked'));
    this.meta.replaceChildren(...tags);

    if (code.kind === 'error') {
      const box = el('div', 'lbe-note error lbe-code-error');
      box.append(el('strong', '', 'These blocks cannot become code yet. '), document.createTextNode(code.message), el('div', 'lbe-hint', 'The blocks are kept as they are; fix them in the Blocks pane.'));
      this.body.replaceChildren(box);
    } else if (code.kind === 'blocks') {
      const pre = el('pre', 'lbe-code lbe-code-view');
      pre.tabIndex = 0;
      pre.setAttribute('aria-label', `The JavaScript of ${fn.name}`);
      for (const t of tokenize(code.source)) pre.appendChild(t.kind === 'text' ? document.createTextNode(t.text) : el('span', `tok-${t.kind}`, t.text));
      this.body.replaceChildren(pre);
    } else {
      this.text.setFrame(fn, layer);
      this.text.setCode(code.code);
      this.text.setReadOnly(locked);
      if (this.text.element.parentElement !== this.body) this.body.replaceChildren(this.text.element);
    }
  }
}
