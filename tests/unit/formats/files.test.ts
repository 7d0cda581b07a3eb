import * as fs from 'node:fs';
import * as os from 'node:os';
import * as path from 'node:path';
import { FileAccessError, readTextFile, writeFileAtomic } from '../../../app/cli/files';

/** Lets a test make the final rename fail, as a full disk or a vanished folder would. */
const failRename: { error: Error | null } = { error: null };
jest.mock('node:fs', () => {
  const actual = jest.requireActual<typeof fs>('node:fs');
  return {
    ...actual,
    renameSync: (from: fs.PathLike, to: fs.PathLike) => {
      if (failRename.error) throw failRename.error;
      actual.renameSync(from, to);
    },
  };
});

let dir: string;
beforeEach(() => {
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'layerbot-files-'));
});
afterEach(() => {
  fs.rmSync(dir, { recursive: true, force: true });
});

function thrown(f: () => unknown): FileAccessError {
  try {
    f();
  } catch (e) {
    if (e instanceof FileAccessError) return e;
    throw e;
  }
  throw new Error('expected a FileAccessError');
}

describe('readTextFile', () => {
  it('reads UTF-8 text', () => {
    const file = path.join(dir, 'a.world.json');
    fs.writeFileSync(file, '{"name": "Café"}');
    expect(readTextFile(file)).toBe('{"name": "Café"}');
  });

  it('reads UTF-16 with a byte-order mark, as some Windows editors save', () => {
    const file = path.join(dir, 'w.json');
    fs.writeFileSync(file, Buffer.concat([Buffer.from([0xff, 0xfe]), Buffer.from('{"a": "é"}', 'utf16le')]));
    expect(readTextFile(file)).toBe('{"a": "é"}');
    const be = Buffer.from('{"b": 1}', 'utf16le');
    be.swap16();
    fs.writeFileSync(file, Buffer.concat([Buffer.from([0xfe, 0xff]), be]));
    expect(readTextFile(file)).toBe('{"b": 1}');
  });

  it('explains a missing file and guesses a typo', () => {
    fs.writeFileSync(path.join(dir, 'office.world.json'), '{}');
    const e = thrown(() => readTextFile(path.join(dir, 'ofice.world.json')));
    expect(e.code).toBe('ENOENT');
    expect(e.message).toBe(`${path.join(dir, 'ofice.world.json')}: no such file; did you mean ${path.join(dir, 'office.world.json')}?`);
    expect(thrown(() => readTextFile(path.join(dir, 'zzz.json'))).message).toBe(`${path.join(dir, 'zzz.json')}: no such file`);
  });

  it('explains a missing folder', () => {
    const file = path.join(dir, 'nowhere', 'a.json');
    expect(thrown(() => readTextFile(file)).message).toBe(`${file}: no such file (the folder ${path.join(dir, 'nowhere')} does not exist either)`);
  });

  it('explains a folder given as a file', () => {
    const e = thrown(() => readTextFile(dir));
    expect(e.code).toBe('EISDIR');
    expect(e.message).toBe(`${dir}: this is a folder, not a file`);
  });

  it('explains bytes that are not text', () => {
    const file = path.join(dir, 'bin.json');
    fs.writeFileSync(file, Buffer.from([0x7b, 0xc3, 0x28, 0x7d]));
    expect(thrown(() => readTextFile(file)).message).toContain('is not a text file');
  });

  const canTestPermissions = process.platform !== 'win32' && process.getuid?.() !== 0;
  (canTestPermissions ? it : it.skip)('explains a file it may not read', () => {
    const file = path.join(dir, 'secret.json');
    fs.writeFileSync(file, '{}');
    fs.chmodSync(file, 0o000);
    expect(thrown(() => readTextFile(file)).message).toBe(`${file}: permission denied; you are not allowed to read this file`);
  });
});

describe('writeFileAtomic', () => {
  const leftovers = () => fs.readdirSync(dir).filter((f) => f.endsWith('.tmp'));

  it('writes a new file and leaves no temporary file', () => {
    const file = path.join(dir, 'out.csv');
    writeFileAtomic(file, 'tick,x\n0,0\n');
    expect(fs.readFileSync(file, 'utf8')).toBe('tick,x\n0,0\n');
    expect(leftovers()).toEqual([]);
  });

  it('replaces an existing file whole and keeps its permissions', () => {
    const file = path.join(dir, 'w.world.json');
    fs.writeFileSync(file, 'old old old old');
    if (process.platform !== 'win32') fs.chmodSync(file, 0o640);
    writeFileAtomic(file, 'new');
    expect(fs.readFileSync(file, 'utf8')).toBe('new');
    if (process.platform !== 'win32') expect(fs.statSync(file).mode & 0o777).toBe(0o640);
    expect(leftovers()).toEqual([]);
  });

  it('explains a missing folder and writes nothing', () => {
    const file = path.join(dir, 'nowhere', 'x.json');
    const e = thrown(() => writeFileAtomic(file, 'x'));
    expect(e.message).toBe(`${file}: cannot write here: the folder ${path.join(dir, 'nowhere')} does not exist`);
    expect(fs.readdirSync(dir)).toEqual([]);
  });

  it('refuses to replace a folder and cleans up', () => {
    const target = path.join(dir, 'sub');
    fs.mkdirSync(target);
    fs.writeFileSync(path.join(target, 'keep'), 'k');
    const e = thrown(() => writeFileAtomic(target, 'x'));
    expect(e.message).toBe(`${target}: this is a folder; cannot write a file in its place`);
    expect(fs.readFileSync(path.join(target, 'keep'), 'utf8')).toBe('k');
    expect(leftovers()).toEqual([]);
  });

  it('removes the temporary file and keeps the old file when the final step fails', () => {
    const file = path.join(dir, 'w.json');
    fs.writeFileSync(file, 'old');
    failRename.error = Object.assign(new Error('no space left on device'), { code: 'ENOSPC' });
    try {
      const e = thrown(() => writeFileAtomic(file, 'new'));
      expect(e.message).toBe(`${file}: cannot write: the disk is full (the old file, if any, is unchanged)`);
    } finally {
      failRename.error = null;
    }
    expect(fs.readFileSync(file, 'utf8')).toBe('old');
    expect(leftovers()).toEqual([]);
  });

  const canTestPermissions = process.platform !== 'win32' && process.getuid?.() !== 0;
  (canTestPermissions ? it : it.skip)('explains a folder it may not write to', () => {
    const ro = path.join(dir, 'ro');
    fs.mkdirSync(ro, 0o500);
    const file = path.join(ro, 'x.json');
    expect(thrown(() => writeFileAtomic(file, 'x')).message).toBe(`${file}: permission denied; you are not allowed to write here`);
    fs.chmodSync(ro, 0o700);
  });
});
