/** Disk access for the main process: atomic writes, the recent-files list and the autosave file. */
import { promises as fs } from 'node:fs';
import { basename, dirname, join } from 'node:path';

/** Writes through a temporary file and a rename, so a crash never leaves half a file. */
export async function writeAtomic(path: string, text: string): Promise<void> {
  const tmp = join(dirname(path), `.${basename(path)}.${process.pid}.tmp`);
  await fs.writeFile(tmp, text, 'utf8');
  await fs.rename(tmp, path);
}

/** The recent files (newest first), kept in a JSON file in the app's data folder. */
export class RecentFiles {
  private list: string[] | null = null;

  constructor(private readonly file: string) {}

  async all(): Promise<string[]> {
    if (this.list) return this.list;
    try {
      const v: unknown = JSON.parse(await fs.readFile(this.file, 'utf8'));
      this.list = Array.isArray(v) ? v.filter((p): p is string => typeof p === 'string').slice(0, 10) : [];
    } catch {
      this.list = [];
    }
    return this.list;
  }

  async add(path: string): Promise<void> {
    const list = [path, ...(await this.all()).filter((p) => p !== path)].slice(0, 10);
    this.list = list;
    await fs.mkdir(dirname(this.file), { recursive: true });
    await writeAtomic(this.file, JSON.stringify(list));
  }

  async has(path: string): Promise<boolean> {
    return (await this.all()).includes(path);
  }
}
