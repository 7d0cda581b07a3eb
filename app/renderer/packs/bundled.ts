/// <reference types="vite/client" />
/** The sample packs from examples/packs, bundled into the build (loaded on demand: they are large). */
const packs = import.meta.glob<string>('../../../examples/packs/*.pack.json', { query: '?raw', import: 'default' });

export interface BundledPack {
  /** The file name, e.g. `intro.pack.json`. */
  readonly file: string;
  load(): Promise<string>;
}

export const BUNDLED_PACKS: readonly BundledPack[] = Object.entries(packs)
  .map(([path, load]) => ({ file: path.slice(path.lastIndexOf('/') + 1), load }))
  .sort((a, b) => a.file.localeCompare(b.file));
