/**
 * Small modal dialogs for the editor (a native `<dialog>`: focus stays inside, Escape cancels):
 * confirm, prompt (Blockly's "new variable" asks through it: Electron has no window.prompt) and
 * a chooser with one button per option.
 */
import { el } from '../panels/dom';

interface DialogParts {
  readonly dialog: HTMLDialogElement;
  readonly body: HTMLElement;
  readonly actions: HTMLElement;
}

function frame(title: string, message?: string): DialogParts {
  const dialog = el('dialog', 'lbe-dialog');
  const h = el('h2', 'lbe-dialog-title', title);
  const body = el('div', 'lbe-dialog-body');
  if (message) body.appendChild(el('p', 'lbe-dialog-message', message));
  const actions = el('div', 'lbe-dialog-actions');
  dialog.append(h, body, actions);
  document.body.appendChild(dialog);
  return { dialog, body, actions };
}

function button(label: string, kind: 'primary' | 'danger' | '' = ''): HTMLButtonElement {
  const b = el('button', `lbe-btn${kind ? ` ${kind}` : ''}`, label);
  b.type = 'button';
  return b;
}

function run<T>(parts: DialogParts, cancelValue: T, wire: (done: (v: T) => void) => void): Promise<T> {
  return new Promise<T>((resolve) => {
    let settled = false;
    const done = (v: T) => {
      if (settled) return;
      settled = true;
      parts.dialog.close();
      parts.dialog.remove();
      resolve(v);
    };
    parts.dialog.addEventListener('cancel', (e) => {
      e.preventDefault();
      done(cancelValue);
    });
    wire(done);
    parts.dialog.showModal();
  });
}

export function confirmDialog(title: string, message: string, ok = 'OK', danger = false): Promise<boolean> {
  const parts = frame(title, message);
  const cancel = button('Cancel');
  const yes = button(ok, danger ? 'danger' : 'primary');
  parts.actions.append(cancel, yes);
  return run(parts, false, (done) => {
    cancel.addEventListener('click', () => done(false));
    yes.addEventListener('click', () => done(true));
    queueMicrotask(() => yes.focus());
  });
}

export function promptDialog(title: string, message: string, value = ''): Promise<string | null> {
  const parts = frame(title, message);
  const input = el('input', 'lbe-input');
  input.value = value;
  input.spellcheck = false;
  parts.body.appendChild(input);
  const cancel = button('Cancel');
  const yes = button('OK', 'primary');
  parts.actions.append(cancel, yes);
  return run<string | null>(parts, null, (done) => {
    cancel.addEventListener('click', () => done(null));
    yes.addEventListener('click', () => done(input.value));
    input.addEventListener('keydown', (e) => {
      if (e.key === 'Enter') done(input.value);
    });
    queueMicrotask(() => {
      input.focus();
      input.select();
    });
  });
}

export function alertDialog(title: string, message: string): Promise<void> {
  const parts = frame(title, message);
  const ok = button('OK', 'primary');
  parts.actions.append(ok);
  return run<void>(parts, undefined, (done) => {
    ok.addEventListener('click', () => done(undefined));
    queueMicrotask(() => ok.focus());
  });
}

/** One choice of `chooseDialog`: a title line and a detail line. */
export interface Choice<T> {
  readonly value: T;
  readonly title: string;
  readonly detail: string;
}

/** Lists the choices as buttons; resolves with the one clicked, or null. */
export function chooseDialog<T>(title: string, message: string, choices: readonly Choice<T>[], extra?: HTMLElement): Promise<T | null> {
  const parts = frame(title, message);
  const list = el('div', 'lbe-choices');
  const buttons = choices.map((c) => {
    const b = el('button', 'lbe-choice');
    b.type = 'button';
    b.append(el('span', 'lbe-choice-title', c.title), el('span', 'lbe-choice-detail', c.detail));
    list.appendChild(b);
    return b;
  });
  parts.body.appendChild(list);
  if (extra) parts.body.appendChild(extra);
  const cancel = button('Cancel');
  parts.actions.append(cancel);
  return run<T | null>(parts, null, (done) => {
    cancel.addEventListener('click', () => done(null));
    buttons.forEach((b, i) => b.addEventListener('click', () => done(choices[i].value)));
    queueMicrotask(() => (buttons[0] ?? cancel).focus());
  });
}
