/** Checks every IPC message from the renderer before the main process acts on it. */
import type { FileKind } from './api';

const KINDS: readonly FileKind[] = ['world', 'controller', 'any'];
/** Files and autosaves larger than this are refused (a runaway controller must not fill the disk). */
export const MAX_TEXT = 50 * 1024 * 1024;

export function isKind(v: unknown): v is FileKind {
  return typeof v === 'string' && (KINDS as readonly string[]).includes(v);
}

export function isText(v: unknown): v is string {
  return typeof v === 'string' && v.length <= MAX_TEXT;
}

/** A plain file name: no folders, no control characters, a sensible length. */
export function isFileName(v: unknown): v is string {
  // eslint-disable-next-line no-control-regex
  return typeof v === 'string' && v.length > 0 && v.length <= 255 && !/[\\/\u0000-\u001f]/.test(v);
}

export function isPath(v: unknown): v is string {
  // eslint-disable-next-line no-control-regex
  return typeof v === 'string' && v.length > 0 && v.length <= 4096 && !/[\u0000]/.test(v);
}
