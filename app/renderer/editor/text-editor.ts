/**
 * The editor's plain-text parts: the JavaScript editor of a text-mode function (the fixed header
 * the engine adds, a textarea for the body, the closing brace) and the "wide editor" button that
 * lets the right-hand pane take most of the window.
 */
import type { FunctionSpec, LayerSpec } from '../../core/controller/model';
import { el } from '../panels/dom';
import { icon } from './icons';
import { functionFrame } from './model';

export class TextEditor {
  readonly element = el('div', 'lbe-text');
  private readonly header = el('pre', 'lbe-code lbe-frame');
  private readonly area = el('textarea', 'lbe-textarea');
  private readonly footer = el('pre', 'lbe-code lbe-frame');
  /** Called with the new text after each edit. */
  onEdit: ((code: string) => void) | null = null;

  constructor() {
    this.area.spellcheck = false;
    this.area.setAttribute('autocapitalize', 'off');
    this.area.setAttribute('autocomplete', 'off');
    this.area.setAttribute('aria-label', 'The function body in JavaScript');
    this.area.wrap = 'off';
    this.area.addEventListener('input', () => this.onEdit?.(this.area.value));
    this.area.addEventListener('keydown', (e) => {
      // Tab indents instead of leaving the editor.
      if (e.key !== 'Tab' || e.ctrlKey || e.altKey || e.metaKey || this.area.readOnly) return;
      e.preventDefault();
      const { selectionStart: a, selectionEnd: b, value } = this.area;
      this.area.value = `${value.slice(0, a)}  ${value.slice(b)}`;
      this.area.selectionStart = this.area.selectionEnd = a + 2;
      this.onEdit?.(this.area.value);
    });
    this.header.title = 'Added by Layerbot: the function header, strict mode and the layer variables.';
    this.element.append(this.header, this.area, this.footer);
  }

  /** Shows `code` unless the user is typing in it (their text is the newest). */
  setCode(code: string): void {
    if (this.area.value === code) return;
    if (document.activeElement === this.area) return;
    this.area.value = code;
  }

  get code(): string {
    return this.area.value;
  }

  setFrame(fn: FunctionSpec, layer: LayerSpec): void {
    const { header, footer } = functionFrame(fn, layer);
    this.header.textContent = header;
    this.footer.textContent = footer;
  }

  setReadOnly(readOnly: boolean): void {
    this.area.readOnly = readOnly;
    this.element.classList.toggle('readonly', readOnly);
  }
}

const WIDE_CLASS = 'lbe-wide';
const wideButtons = new Set<HTMLButtonElement>();

function renderWide(): void {
  const wide = !!document.getElementById('app')?.classList.contains(WIDE_CLASS);
  for (const b of wideButtons) {
    b.replaceChildren(icon(wide ? 'shrink' : 'expand'));
    b.title = wide ? 'Narrow the editor (show more of the world)' : 'Widen the editor';
    b.setAttribute('aria-label', b.title);
    b.setAttribute('aria-pressed', String(wide));
  }
}

/** A button that widens the right-hand pane over most of the centre (for every pane). */
export function expandButton(): HTMLButtonElement {
  const b = el('button', 'lbe-icon-btn lbe-expand');
  b.type = 'button';
  b.dataset.action = 'expand';
  b.addEventListener('click', () => {
    document.getElementById('app')?.classList.toggle(WIDE_CLASS);
    renderWide();
  });
  wideButtons.add(b);
  renderWide();
  return b;
}
