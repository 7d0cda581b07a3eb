/**
 * The About panel: what the open world and controller are for, in their authors' words (their
 * `description` fields), with each layer's own description. A student reads it first when an
 * example opens.
 */
import type { ControllerSpec } from '../../core/controller/model';
import type { WorldSpec } from '../../core/world/world';
import { el } from './dom';

export class AboutPanel {
  constructor(private readonly root: HTMLElement) {}

  show(world: WorldSpec, controller: ControllerSpec | null): void {
    const worldPart = el('section', 'about-part');
    worldPart.append(el('h3', 'about-kind', 'World'), el('h4', 'about-name', world.name));
    worldPart.append(el('p', 'about-text', world.description?.trim() || 'This world has no description.'));
    const facts = `${count(world.walls.length, 'wall')} · ${count(world.goals.length, 'goal')} · plan: ${world.plan.length ? world.plan.join(' → ') : 'empty'}`;
    worldPart.append(el('p', 'about-facts', facts));

    const ctrlPart = el('section', 'about-part');
    ctrlPart.append(el('h3', 'about-kind', 'Controller'));
    if (!controller) {
      ctrlPart.append(el('p', 'about-text', 'No controller is open. Open one from File › Example controllers, or build your own in the Blocks pane.'));
    } else {
      ctrlPart.append(el('h4', 'about-name', controller.name));
      ctrlPart.append(el('p', 'about-text', controller.description?.trim() || 'This controller has no description.'));
      const layers = el('ol', 'about-layers');
      for (const layer of controller.layers) {
        const li = el('li');
        const functions = layer.functions.map((f) => f.name).join(', ') || 'no functions';
        li.append(el('b', undefined, layer.name), el('span', 'about-fns', ` ${functions}`));
        if (layer.description?.trim()) li.append(el('div', 'about-layer-text', layer.description.trim()));
        layers.append(li);
      }
      ctrlPart.append(layers);
    }
    this.root.replaceChildren(el('div', 'about'));
    this.root.firstElementChild!.append(worldPart, ctrlPart);
  }
}

function count(n: number, what: string): string {
  return `${n} ${what}${n === 1 ? '' : 's'}`;
}
