/** The timeline: slider, tick number, back and forward. It only selects ticks; the app shows them. */
import { byId } from './dom';

export class Timeline {
  private readonly slider = byId<HTMLInputElement>('tl-slider');
  private readonly number = byId<HTMLInputElement>('tl-number');
  private readonly of = byId('tl-of');
  private max = 0;

  constructor(private readonly select: (tick: number) => void) {
    this.slider.addEventListener('input', () => this.select(Number(this.slider.value)));
    this.number.addEventListener('change', () => this.select(this.clamp(Number(this.number.value))));
    this.number.addEventListener('keydown', (e) => {
      if (e.key === 'Enter') this.select(this.clamp(Number(this.number.value)));
    });
    byId('tl-first').addEventListener('click', () => this.select(0));
    byId('tl-back').addEventListener('click', () => this.select(this.clamp(Number(this.slider.value) - 1)));
    byId('tl-fwd').addEventListener('click', () => this.select(this.clamp(Number(this.slider.value) + 1)));
    byId('tl-last').addEventListener('click', () => this.select(this.max));
  }

  clamp(t: number): number {
    return Number.isFinite(t) ? Math.max(0, Math.min(this.max, Math.round(t))) : 0;
  }

  /** Shows `tick` selected out of ticks 0..max. */
  show(tick: number, max: number): void {
    this.max = max;
    this.slider.max = String(max);
    this.slider.value = String(tick);
    this.number.max = String(max);
    if (document.activeElement !== this.number) this.number.value = String(tick);
    this.of.textContent = `of ${max}`;
  }
}
