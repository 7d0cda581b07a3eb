/**
 * PLACEHOLDER until the diagram lands: the diagram engineer replaces this pane (keep the export).
 */
import type { ControllerPane, PaneHost } from '../panes/types';

/** The controller diagram pane. */
export function diagramPane(): ControllerPane {
  return {
    id: 'diagram',
    title: 'Diagram',
    mount(element: HTMLElement, _host: PaneHost): void {
      const p = document.createElement('div');
      p.className = 'empty-state';
      p.innerHTML = '<div><b>The controller diagram</b>Layers as bands, functions as ovals, arcs as arrows — coming soon.</div>';
      element.appendChild(p);
    },
  };
}
