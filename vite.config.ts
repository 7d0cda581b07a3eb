/**
 * Builds the renderer (app/renderer) into dist/web: one page, one engine Worker, Blockly's media.
 * The base is relative so the same build loads from the static server (`npm run web`) and from
 * Electron's app:// protocol. Nothing is fetched from the network at run time.
 */
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, resolve } from 'node:path';
import type { Plugin } from 'vite';
import { defineConfig } from 'vite';

const BLOCKLY_MEDIA = resolve(__dirname, 'node_modules/blockly/media');

/** Ships Blockly's media folder as `media/` (Blockly would otherwise load it from Google's host). */
function blocklyMedia(): Plugin {
  return {
    name: 'layerbot-blockly-media',
    generateBundle() {
      for (const name of readdirSync(BLOCKLY_MEDIA)) {
        const file = join(BLOCKLY_MEDIA, name);
        if (statSync(file).isFile()) this.emitFile({ type: 'asset', fileName: `media/${name}`, source: readFileSync(file) });
      }
    },
    configureServer(server) {
      server.middlewares.use('/media', (req, res, next) => {
        const name = (req.url ?? '').replace(/^\/+/, '').split('?')[0];
        const file = join(BLOCKLY_MEDIA, name);
        if (!name || name.includes('..') || !statSync(file, { throwIfNoEntry: false })?.isFile()) return next();
        res.end(readFileSync(file));
      });
    },
  };
}

export default defineConfig({
  root: resolve(__dirname, 'app/renderer'),
  base: './',
  publicDir: false,
  plugins: [blocklyMedia()],
  worker: { format: 'es' },
  build: {
    // LAYERBOT_WEB_DIR builds elsewhere (the static server and the browser tests read it too).
    outDir: process.env.LAYERBOT_WEB_DIR ? resolve(process.env.LAYERBOT_WEB_DIR) : resolve(__dirname, 'dist/web'),
    emptyOutDir: true,
    target: 'es2022',
    sourcemap: true,
    // Blockly and PixiJS are large; one chunk each keeps caching simple and the warning quiet.
    chunkSizeWarningLimit: 2500,
  },
  server: { host: '127.0.0.1', port: 5173, strictPort: false },
});
