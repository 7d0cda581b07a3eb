/// <reference types="vite/client" />
/**
 * The example worlds and controllers from examples/, bundled into the build (the app works
 * offline). Worlds are small and included; controllers load on demand, each in its own chunk.
 */
const worlds = import.meta.glob<string>('../../../examples/worlds/*.world.json', { query: '?raw', import: 'default', eager: true });
const controllers = import.meta.glob<string>('../../../examples/controllers/*.controller.json', { query: '?raw', import: 'default' });

export interface ExampleEntry {
  /** The file name, e.g. `office.world.json`. */
  readonly file: string;
  /** A readable title, e.g. `office`. */
  readonly title: string;
  load(): Promise<string>;
}

const baseName = (path: string): string => path.slice(path.lastIndexOf('/') + 1);
const title = (file: string): string => file.replace(/\.(world|controller)\.json$/, '');

export const EXAMPLE_WORLDS: readonly ExampleEntry[] = Object.entries(worlds)
  .map(([path, text]) => ({ file: baseName(path), title: title(baseName(path)), load: () => Promise.resolve(text) }))
  .sort((a, b) => a.title.localeCompare(b.title));

export const EXAMPLE_CONTROLLERS: readonly ExampleEntry[] = Object.entries(controllers)
  .map(([path, load]) => ({ file: baseName(path), title: title(baseName(path)), load }))
  .sort((a, b) => a.title.localeCompare(b.title));
