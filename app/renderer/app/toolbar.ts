/** The top toolbar: mode switch, run controls, speed, status line and the theme toggle. */
import type { EngineSnapshot } from '../engine/client';
import { byId, el } from '../panels/dom';
import type { App } from './app';

/** Speed slider stops in ticks per second; the last is "as fast as the engine can go". */
const SPEEDS = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 0];
const THEME_KEY = 'layerbot.theme';
const NOTICE_MS = 6000;

export class Toolbar {
  private readonly slider = byId<HTMLInputElement>('speed');
  private readonly status = byId('status');
  private notice: { text: string; kind: 'info' | 'error'; until: number } | null = null;
  private lastStatus = '';

  constructor(private readonly app: App) {
    for (const b of byId('mode-switch').querySelectorAll<HTMLButtonElement>('[data-mode]')) {
      b.addEventListener('click', () => app.store.setMode(b.dataset.mode === 'create' ? 'create' : 'solve'));
    }
    app.store.onMode.on(() => this.renderMode());
    byId('btn-step').addEventListener('click', () => app.step());
    byId('btn-run').addEventListener('click', () => app.toggleRun());
    byId('btn-reset').addEventListener('click', () => app.reset());
    byId('zoom-in').addEventListener('click', () => app.view.zoomAt(app.view.camera.width / 2, app.view.camera.height / 2, 1.25));
    byId('zoom-out').addEventListener('click', () => app.view.zoomAt(app.view.camera.width / 2, app.view.camera.height / 2, 0.8));
    byId('zoom-fit').addEventListener('click', () => app.fit());
    this.slider.addEventListener('input', () => {
      this.renderSpeed();
      app.setSpeed(this.speed());
    });
    const theme = byId('theme-toggle');
    theme.addEventListener('click', () => this.setTheme(document.documentElement.dataset.theme !== 'contrast'));
    this.setTheme(localStorage.getItem(THEME_KEY) === 'contrast');
    app.store.onNotice.on((n) => {
      this.notice = { ...n, until: performance.now() + NOTICE_MS };
      this.lastStatus = '';
      app.invalidate();
      setTimeout(() => app.invalidate(), NOTICE_MS + 50);
    });
    this.renderSpeed();
    this.renderMode();
  }

  /** The chosen speed in ticks per second (0: full speed). */
  speed(): number {
    return SPEEDS[Number(this.slider.value)] ?? 0;
  }

  private renderSpeed(): void {
    const s = this.speed();
    byId('speed-out').textContent = s === 0 ? 'max' : `${s}/s`;
  }

  private setTheme(contrast: boolean): void {
    document.documentElement.dataset.theme = contrast ? 'contrast' : 'light';
    byId('theme-toggle').setAttribute('aria-pressed', String(contrast));
    try {
      localStorage.setItem(THEME_KEY, contrast ? 'contrast' : 'light');
    } catch {
      // The theme is a preference; not saving it is harmless.
    }
    this.app.view.refreshPalette();
    this.app.invalidate();
  }

  private renderMode(): void {
    for (const b of byId('mode-switch').querySelectorAll<HTMLButtonElement>('[data-mode]')) {
      b.setAttribute('aria-selected', String(b.dataset.mode === this.app.store.mode));
    }
  }

  /** Updates the run button and the status line (cheap when nothing changed). */
  render(state: EngineSnapshot, tick: number, latest: number, fps: number): void {
    byId('app').classList.toggle('running', state.running);
    byId('btn-run').querySelector('.label')!.textContent = state.running ? 'Stop' : 'Run';
    const [kind, text] = this.describe(state, latest);
    const notice = this.notice && this.notice.until > performance.now() ? this.notice : null;
    const key = `${kind}|${text}|${notice?.text ?? ''}|${state.running ? Math.round(state.ticksPerSecond / 50) : ''}`;
    if (key === this.lastStatus) return;
    this.lastStatus = key;
    const pill = el('span', `pill ${kind}`, text);
    pill.dataset.status = state.running ? 'running' : state.status;
    const parts: HTMLElement[] = [pill];
    if (state.running && state.ticksPerSecond > 0) {
      const rate = el('span', 'notice', `${Math.round(state.ticksPerSecond).toLocaleString()} ticks/s`);
      rate.title = `${Math.round(fps)} frames per second`;
      parts.push(rate);
    }
    if (notice) parts.push(el('span', `notice${notice.kind === 'error' ? ' err' : ''}`, notice.text));
    else if (state.note && !state.running) parts.push(el('span', 'notice', state.note));
    this.status.replaceChildren(...parts);
    void tick;
  }

  private describe(state: EngineSnapshot, latest: number): [string, string] {
    if (!state.hasController) return ['', 'No controller'];
    if (state.running) return ['run', `Running · tick ${latest}`];
    const s = state.summary;
    switch (state.status) {
      case 'done':
        return ['ok', `Plan complete at tick ${latest}`];
      case 'crashed':
        return ['err', `Crashed at tick ${s?.crashTick ?? latest}`];
      case 'error':
        return ['err', `Error at tick ${latest}`];
      default:
        return latest === 0 ? ['', 'Ready'] : ['warn', `Paused at tick ${latest}`];
    }
  }
}
