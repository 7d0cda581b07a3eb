/**
 * Browser tests: checks that Chromium and the web build exist (failing with instructions, never
 * skipping), then starts the app's own static server (app/main/serve.mjs) on a free port.
 */
import { spawn } from 'node:child_process';
import { existsSync } from 'node:fs';
import { join } from 'node:path';

export const CHROMIUM = process.env.LAYERBOT_CHROMIUM ?? '/usr/bin/chromium';
const ROOT = join(__dirname, '../..');

export default async function globalSetup(): Promise<void> {
  if (!existsSync(CHROMIUM)) {
    throw new Error(
      `Browser tests need Chromium at ${CHROMIUM}, and it is missing.\n` +
        'Install it (Debian/Ubuntu: sudo apt-get install -y chromium) or point LAYERBOT_CHROMIUM at a Chromium binary.',
    );
  }
  const web = process.env.LAYERBOT_WEB_DIR ?? join(ROOT, 'dist/web');
  if (!existsSync(join(web, 'index.html'))) {
    throw new Error(`Browser tests need the web build in ${web}. Run \`npm run build:web\` first (\`npm test\` does it).`);
  }
  const child = spawn(process.execPath, [join(ROOT, 'app/main/serve.mjs'), '--port', '0'], { stdio: ['ignore', 'pipe', 'pipe'] });
  const url = await new Promise<string>((resolve, reject) => {
    let out = '';
    const timer = setTimeout(() => reject(new Error(`The static server did not start: ${out}`)), 15_000);
    child.stdout.on('data', (d: Buffer) => {
      out += d.toString();
      const m = /(http:\/\/127\.0\.0\.1:\d+\/)/.exec(out);
      if (m) {
        clearTimeout(timer);
        resolve(m[1]);
      }
    });
    child.stderr.on('data', (d: Buffer) => (out += d.toString()));
    child.on('exit', (code) => reject(new Error(`The static server exited (${code}): ${out}`)));
  });
  process.env.LAYERBOT_URL = url;
  process.env.LAYERBOT_CHROMIUM = CHROMIUM;
  (globalThis as { layerbotServer?: typeof child }).layerbotServer = child;
}
