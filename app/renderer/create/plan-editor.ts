/** The plan card: the goals to visit in order; add, remove, reorder (each an undoable edit). */
import type { Store } from '../app/store';
import { byId, el } from '../panels/dom';

export class PlanEditor {
  private readonly list = byId<HTMLOListElement>('plan-list');
  private readonly picker = byId<HTMLSelectElement>('plan-add-goal');

  constructor(private readonly store: Store) {
    byId('plan-add').addEventListener('click', () => {
      if (this.picker.value) this.setPlan([...store.world.plan, this.picker.value]);
    });
    store.onWorld.on(() => this.render());
    this.render();
  }

  private setPlan(plan: string[]): void {
    this.store.editWorld({ type: 'setPlan', plan });
  }

  private render(): void {
    const { plan, goals } = this.store.world;
    const items: HTMLElement[] = plan.map((name, i) => {
      const li = el('li');
      li.appendChild(el('span', 'name', name));
      const up = el('button', undefined, '↑');
      up.title = 'Earlier';
      up.disabled = i === 0;
      up.addEventListener('click', () => {
        const p = [...plan];
        [p[i - 1], p[i]] = [p[i], p[i - 1]];
        this.setPlan(p);
      });
      const down = el('button', undefined, '↓');
      down.title = 'Later';
      down.disabled = i === plan.length - 1;
      down.addEventListener('click', () => {
        const p = [...plan];
        [p[i + 1], p[i]] = [p[i], p[i + 1]];
        this.setPlan(p);
      });
      const remove = el('button', undefined, '×');
      remove.title = 'Remove from the plan';
      remove.addEventListener('click', () => this.setPlan(plan.filter((_p, j) => j !== i)));
      li.append(up, down, remove);
      return li;
    });
    if (!items.length) items.push(el('li', 'empty', goals.length ? 'Empty: add goals below.' : 'Place goals first, then add them here.'));
    this.list.replaceChildren(...items);
    const keep = this.picker.value;
    this.picker.replaceChildren(...goals.map((g) => {
      const o = el('option', undefined, g.name);
      o.value = g.name;
      return o;
    }));
    if (goals.some((g) => g.name === keep)) this.picker.value = keep;
    this.picker.disabled = goals.length === 0;
  }
}
