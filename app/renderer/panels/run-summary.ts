/** The Run card in Solve mode: tick, status, and each plan step with the tick it was reached. */
import type { TickFrame, WorldParts } from '../engine/protocol';
import { byId, el } from './dom';

export class RunSummary {
  private readonly root = byId('run-summary');

  show(frame: TickFrame | undefined, world: WorldParts | undefined, latest: number, hasController: boolean): void {
    if (!frame || !world) return;
    const stat = (k: string, v: string): HTMLElement => {
      const d = el('div', 'stat');
      d.append(el('span', undefined, k), el('b', undefined, v));
      return d;
    };
    const parts: HTMLElement[] = [stat('Tick shown', `${frame.tick} / ${latest}`), stat('Position', `${frame.x.toFixed(1)}, ${frame.y.toFixed(1)}`), stat('Heading', `${frame.heading.toFixed(0)}°`)];
    if (!hasController) parts.push(el('p', 'hint', 'Open a controller (File › Example controllers) to run the robot.'));
    const goals = el('ul', 'goals');
    const next = frame.reached.indexOf(null);
    world.plan.forEach((name, i) => {
      const t = frame.reached[i];
      const li = el('li', t !== null && t !== undefined ? 'done' : i === next ? 'next' : undefined);
      li.append(el('span', undefined, `${i + 1}. ${name}`), el('span', 't', t !== null && t !== undefined ? `tick ${t}` : i === next ? 'next' : '—'));
      goals.appendChild(li);
    });
    if (world.plan.length) parts.push(goals);
    this.root.replaceChildren(...parts);
  }
}
