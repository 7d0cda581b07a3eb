/**
 * PLACEHOLDER pane: a read-only outline of the controller (layers, functions, their inputs), so
 * the app is usable before the block editor lands. The editor engineer replaces it.
 */
import type { ControllerSpec } from '../../core/controller/model';
import type { ControllerError } from '../../core/session/types';
import type { ControllerPane, PaneHost } from '../panes/types';

function describeSource(from: ControllerSpec['layers'][number]['functions'][number]['inputs'][number]['from']): string {
  switch (from.kind) {
    case 'function':
      return from.function;
    case 'previous':
      return `${from.function} (previous tick)`;
    case 'world':
      return `world.${from.input}`;
    case 'random':
      return `random ${from.source}`;
  }
}

export class OutlinePane implements ControllerPane {
  private el: HTMLElement | null = null;
  private error: ControllerError | null = null;

  constructor(
    readonly id: string,
    readonly title: string,
  ) {}

  mount(element: HTMLElement, host: PaneHost): void {
    this.el = element;
    this.render(host.controller());
    host.onControllerOpened((spec) => this.render(spec));
    host.onError((e) => {
      this.error = e;
      this.render(host.controller());
    });
  }

  revealError(error: ControllerError): boolean {
    this.error = error;
    const target = this.el?.querySelector(`[data-function="${CSS.escape(error.function ?? '')}"]`);
    target?.scrollIntoView({ block: 'center' });
    return this.id === 'blocks' && target !== null;
  }

  private render(spec: ControllerSpec | null): void {
    const el = this.el;
    if (!el) return;
    el.replaceChildren();
    const wrap = document.createElement('div');
    wrap.className = 'pane-placeholder';
    const note = document.createElement('p');
    note.className = 'hint';
    note.textContent =
      this.id === 'code' ? 'The generated JavaScript of each function will appear here.' : 'The block editor will appear here. For now, the controller’s outline:';
    wrap.appendChild(note);
    if (!spec) {
      const p = document.createElement('p');
      p.textContent = 'No controller is open. Open one from File › Example controllers.';
      wrap.appendChild(p);
    } else if (this.id !== 'code') {
      const h = document.createElement('h3');
      h.textContent = spec.name;
      wrap.appendChild(h);
      for (const layer of spec.layers) {
        const box = document.createElement('section');
        box.className = 'outline-layer';
        const title = document.createElement('h3');
        title.textContent = layer.name;
        const vars = document.createElement('span');
        vars.textContent = layer.variables.map((v) => `${v.name} = ${JSON.stringify(v.value)}`).join(', ');
        title.appendChild(vars);
        box.appendChild(title);
        for (const fn of layer.functions) {
          const f = document.createElement('div');
          f.className = 'outline-fn' + (this.error?.function === fn.name ? ' error' : '');
          f.dataset.function = fn.name;
          const sig = document.createElement('div');
          sig.className = 'sig';
          const b = document.createElement('b');
          b.textContent = fn.name;
          sig.append(b, ` → ${fn.output}${fn.name === spec.bodyCommand ? '  (body command)' : ''}`);
          const inputs = document.createElement('div');
          inputs.className = 'inputs';
          inputs.textContent = fn.inputs.length ? fn.inputs.map((i) => `${i.name} ← ${describeSource(i.from)}`).join(' · ') : 'no inputs';
          f.append(sig, inputs);
          box.appendChild(f);
        }
        wrap.appendChild(box);
      }
    }
    el.appendChild(wrap);
  }
}
