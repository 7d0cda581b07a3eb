/**
 * Reading and writing files for the command line (and the Electron main process), with errors
 * that say what went wrong in plain words. Writes are atomic: the text goes to a temporary file in
 * the same folder, is flushed to disk, and then renamed over the target, so a crash or a full disk
 * never leaves a half-written world, controller or trace behind.
 */
import * as fs from 'node:fs';
import * as path from 'node:path';
import { randomBytes } from 'node:crypto';

/** A file could not be read or written; the message names the file and says why. */
export class FileAccessError extends Error {
  constructor(
    readonly file: string,
    /** The Node error code, such as ENOENT, when there was one. */
    readonly code: string | undefined,
    message: string,
  ) {
    super(message);
    this.name = 'FileAccessError';
  }
}

/**
 * Reads a text file (UTF-8, or UTF-16 with a byte-order mark as some Windows editors write).
 * Throws a FileAccessError for a missing file, a folder, a file without read permission, or
 * bytes that are not text.
 */
export function readTextFile(file: string): string {
  let bytes: Buffer;
  try {
    if (fs.statSync(file).isDirectory()) throw new FileAccessError(file, 'EISDIR', `${file}: this is a folder, not a file`);
    bytes = fs.readFileSync(file);
  } catch (e) {
    if (e instanceof FileAccessError) throw e;
    throw readError(file, e);
  }
  return decodeText(file, bytes);
}

function decodeText(file: string, bytes: Buffer): string {
  if (bytes[0] === 0xff && bytes[1] === 0xfe) return bytes.subarray(2).toString('utf16le');
  if (bytes[0] === 0xfe && bytes[1] === 0xff) {
    const swapped = Buffer.from(bytes.subarray(2));
    swapped.swap16();
    return swapped.toString('utf16le');
  }
  try {
    return new TextDecoder('utf-8', { fatal: true }).decode(bytes);
  } catch {
    throw new FileAccessError(file, undefined, `${file}: this is not a text file (it is not UTF-8); save it as UTF-8 text`);
  }
}

function readError(file: string, e: unknown): FileAccessError {
  const code = errorCode(e);
  switch (code) {
    case 'ENOENT': {
      const dir = path.dirname(file);
      if (!fs.existsSync(dir)) return new FileAccessError(file, code, `${file}: no such file (the folder ${dir} does not exist either)`);
      const guess = similarName(dir, path.basename(file));
      return new FileAccessError(file, code, `${file}: no such file${guess ? `; did you mean ${path.join(dir, guess)}?` : ''}`);
    }
    case 'ENOTDIR':
      return new FileAccessError(file, code, `${file}: no such file (a part of the path is a file, not a folder)`);
    case 'EISDIR':
      return new FileAccessError(file, code, `${file}: this is a folder, not a file`);
    case 'EACCES':
    case 'EPERM':
      return new FileAccessError(file, code, `${file}: permission denied; you are not allowed to read this file`);
    case 'ERR_FS_FILE_TOO_LARGE':
      return new FileAccessError(file, code, `${file}: the file is too large to read`);
    default:
      return new FileAccessError(file, code, `${file}: cannot read the file (${e instanceof Error ? e.message : String(e)})`);
  }
}

/** A file in `dir` whose name differs from `name` only a little (a typo), if any. */
function similarName(dir: string, name: string): string | undefined {
  let entries: string[];
  try {
    entries = fs.readdirSync(dir);
  } catch {
    return undefined;
  }
  const lower = name.toLowerCase();
  let best: string | undefined;
  let bestDistance = Math.max(2, Math.floor(name.length / 4)) + 1;
  for (const entry of entries) {
    const d = editDistance(lower, entry.toLowerCase());
    if (d < bestDistance) {
      best = entry;
      bestDistance = d;
    }
  }
  return best;
}

function editDistance(a: string, b: string): number {
  let prev = Array.from({ length: b.length + 1 }, (_, j) => j);
  for (let i = 1; i <= a.length; i++) {
    const cur = [i];
    for (let j = 1; j <= b.length; j++) cur[j] = Math.min(prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] === b[j - 1] ? 0 : 1));
    prev = cur;
  }
  return prev[b.length];
}

/**
 * Writes `text` (UTF-8) to `file` atomically: a temporary file in the same folder (so the rename
 * stays on one file system and is atomic), fsync, then rename over the target. An existing
 * target keeps its permissions. On any failure the temporary file is removed and the target is
 * left as it was; the FileAccessError says why.
 */
export function writeFileAtomic(file: string, text: string): void {
  const dir = path.dirname(path.resolve(file));
  const temp = path.join(dir, `.${path.basename(file)}.${process.pid}.${randomBytes(6).toString('hex')}.tmp`);
  let fd: number | undefined;
  try {
    let mode = 0o666;
    try {
      const st = fs.statSync(file);
      if (st.isDirectory()) throw new FileAccessError(file, 'EISDIR', `${file}: this is a folder; cannot write a file in its place`);
      mode = st.mode & 0o7777;
    } catch (e) {
      if (e instanceof FileAccessError) throw e;
      if (errorCode(e) !== 'ENOENT') throw e;
    }
    // 'wx': fail rather than write through a file (or link) that someone else created at this name.
    fd = fs.openSync(temp, 'wx', mode);
    fs.writeFileSync(fd, text, 'utf8');
    fs.fsyncSync(fd);
    fs.closeSync(fd);
    fd = undefined;
    renameWithRetry(temp, file);
  } catch (e) {
    if (fd !== undefined) {
      try {
        fs.closeSync(fd);
      } catch {
        // Already failing; the original error is the one to report.
      }
    }
    try {
      fs.rmSync(temp, { force: true });
    } catch {
      // Nothing more we can do; the original error is the one to report.
    }
    throw e instanceof FileAccessError ? e : writeError(file, e);
  }
  syncDirectory(dir);
}

/**
 * Windows refuses to replace a file that another program (a virus scanner, an editor) holds open
 * for a moment; a few short retries get past that. Elsewhere rename is atomic and retries never run.
 */
function renameWithRetry(from: string, to: string): void {
  for (let attempt = 0; ; attempt++) {
    try {
      fs.renameSync(from, to);
      return;
    } catch (e) {
      const code = errorCode(e);
      if (process.platform !== 'win32' || attempt >= 5 || !(code === 'EPERM' || code === 'EACCES' || code === 'EBUSY')) throw e;
      Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 0, 20 * (attempt + 1));
    }
  }
}

/** Makes the rename itself durable. Not every system can open a folder (Windows cannot): best effort. */
function syncDirectory(dir: string): void {
  let fd: number | undefined;
  try {
    fd = fs.openSync(dir, 'r');
    fs.fsyncSync(fd);
  } catch {
    // The data is written and renamed; only durability across a power cut is weaker here.
  } finally {
    if (fd !== undefined) fs.closeSync(fd);
  }
}

function writeError(file: string, e: unknown): FileAccessError {
  const code = errorCode(e);
  switch (code) {
    case 'ENOENT':
    case 'ENOTDIR':
      return new FileAccessError(file, code, `${file}: cannot write here: the folder ${path.dirname(file)} does not exist`);
    case 'EISDIR':
      return new FileAccessError(file, code, `${file}: this is a folder; cannot write a file in its place`);
    case 'EACCES':
    case 'EPERM':
      return new FileAccessError(file, code, `${file}: permission denied; you are not allowed to write here`);
    case 'EROFS':
      return new FileAccessError(file, code, `${file}: cannot write: the disk is read-only`);
    case 'ENOSPC':
      return new FileAccessError(file, code, `${file}: cannot write: the disk is full (the old file, if any, is unchanged)`);
    default:
      return new FileAccessError(file, code, `${file}: cannot write the file (${e instanceof Error ? e.message : String(e)})`);
  }
}

function errorCode(e: unknown): string | undefined {
  return typeof e === 'object' && e !== null && 'code' in e && typeof e.code === 'string' ? e.code : undefined;
}
