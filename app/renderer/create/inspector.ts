/** The selection card in Create mode: edit the selected goal's name and place, the robot, a wall. */
import type { WorldEdit } from '../../core/world/edits';
import type { Store } from '../app/store';
import { byId, el } from '../panels/dom';
import type { CreateState } from './selection';

export class Inspector {
  private readonly root = byId('inspector');

  constructor(
    private readonly create: CreateState,
    private readonly store: Store,
  ) {
    create.onChange.on(() => this.render());
    store.onWorld.on(() => this.render());
    create.onNameGoal.on(() => {
      const input = this.root.querySelector<HTMLInputElement>('input[data-field="name"]');
      input?.focus();
      input?.select();
    });
    this.render();
  }

  private field(label: string, name: string, value: string | number, commit: (v: string) => void, type = 'number'): HTMLElement[] {
    const l = el('label', undefined, label);
    const input = el('input');
    input.type = type;
    input.value = String(value);
    input.dataset.field = name;
    input.id = `insp-${name}`;
    l.htmlFor = input.id;
    if (type === 'number') input.step = 'any';
    const apply = (): void => {
      if (input.value !== String(value)) commit(input.value);
    };
    input.addEventListener('change', apply);
    input.addEventListener('keydown', (e) => {
      if (e.key === 'Enter') apply();
      if (e.key === 'Escape') input.blur();
    });
    return [l, input];
  }

  private edit(edit: WorldEdit): void {
    this.store.editWorld(edit);
  }

  private render(): void {
    const s = this.create.selection;
    const w = this.store.world;
    const title = el('h2', undefined, 'Selection');
    const grid = el('div', 'inspector-grid');
    const num = (v: string): number => Number(v);
    if (s?.kind === 'goal') {
      const g = w.goals.find((q) => q.name === s.name);
      if (!g) return this.create.select(null);
      grid.append(
        ...this.field('Name', 'name', g.name, (v) => {
          const name = v.trim();
          if (!name) return this.store.notice('A goal needs a name.', 'error');
          if (this.store.editWorld({ type: 'setGoal', name: g.name, goal: { ...g, name } })) this.create.select({ kind: 'goal', name });
        }, 'text'),
        ...this.field('x', 'x', g.x, (v) => this.edit({ type: 'setGoal', name: g.name, goal: { ...g, x: num(v) } })),
        ...this.field('y', 'y', g.y, (v) => this.edit({ type: 'setGoal', name: g.name, goal: { ...g, y: num(v) } })),
      );
      const add = el('button', 'small', 'Add to plan');
      add.addEventListener('click', () => this.edit({ type: 'setPlan', plan: [...w.plan, g.name] }));
      const row = el('div', 'row');
      row.appendChild(add);
      this.root.replaceChildren(title, grid, row);
    } else if (s?.kind === 'robot') {
      const r = w.robot;
      grid.append(
        ...this.field('x', 'x', r.x, (v) => this.edit({ type: 'moveRobot', x: num(v), y: r.y })),
        ...this.field('y', 'y', r.y, (v) => this.edit({ type: 'moveRobot', x: r.x, y: num(v) })),
        ...this.field('Heading', 'heading', r.heading, (v) => this.edit({ type: 'moveRobot', x: r.x, y: r.y, heading: num(v) })),
      );
      this.root.replaceChildren(title, grid);
    } else if (s?.kind === 'wall' && w.walls[s.index]) {
      const [[x0, y0], [x1, y1]] = w.walls[s.index];
      const set = (a: number, b: number, c: number, d: number): void => this.edit({ type: 'setWall', index: s.index, wall: [[a, b], [c, d]] });
      grid.append(
        ...this.field('x₀', 'x0', x0, (v) => set(num(v), y0, x1, y1)),
        ...this.field('y₀', 'y0', y0, (v) => set(x0, num(v), x1, y1)),
        ...this.field('x₁', 'x1', x1, (v) => set(x0, y0, num(v), y1)),
        ...this.field('y₁', 'y1', y1, (v) => set(x0, y0, x1, num(v))),
      );
      const del = el('button', 'small', 'Delete wall');
      del.addEventListener('click', () => {
        this.edit({ type: 'removeWall', index: s.index });
        this.create.select(null);
      });
      const row = el('div', 'row');
      row.appendChild(del);
      this.root.replaceChildren(title, grid, row);
    } else {
      const hint = el('p', 'hint', 'Click the robot, a goal or a wall to edit it. Drag to move; drag a wall’s end to stretch it.');
      hint.style.margin = '0';
      const name = el('div', 'inspector-grid');
      name.append(...this.field('World', 'world-name', w.name, (v) => this.store.renameWorld(v.trim() || 'Untitled world'), 'text'));
      name.style.marginTop = '10px';
      this.root.replaceChildren(title, hint, name);
    }
  }
}
