/**
 * The envelope every Layerbot file shares: `"format"` says what the file is, `"version"` which
 * version of that format wrote it. Readers check both before the schema, so a controller opened
 * as a world gets one clear sentence instead of a page of schema errors, and old files are
 * migrated to the current version before they are validated.
 */
import type { FileProblem } from './types';
import type { JsonDocument } from './json';
import { describeFound } from './validator';

/** The kinds of Layerbot file, by their `format` value. */
export const FORMATS = {
  world: 'layerbot-world',
  controller: 'layerbot-controller',
  pack: 'layerbot-pack',
} as const;
export type FileKind = keyof typeof FORMATS;

const KIND_NAMES: Record<FileKind, string> = { world: 'world', controller: 'controller', pack: 'challenge pack' };

/** The version each format's writer writes, and the newest its reader understands. */
export const CURRENT_VERSION: Record<FileKind, number> = { world: 1, controller: 1, pack: 1 };

/** A step from one version's JSON to the next version's; `migrations[kind][v]` turns v into v + 1. */
export type Migration = (doc: Record<string, unknown>) => Record<string, unknown>;

/**
 * Migrations per format. Version 1 is the first and current version of every format, so there
 * are none yet; when version 2 comes, `world: { 1: (doc) => ... }` upgrades old files on load.
 */
export const MIGRATIONS: Record<FileKind, Readonly<Record<number, Migration>>> = { world: {}, controller: {}, pack: {} };

/** The kind a `format` value names, if any. */
export function kindOfFormat(format: unknown): FileKind | undefined {
  return (Object.keys(FORMATS) as FileKind[]).find((k) => FORMATS[k] === format);
}

/**
 * Checks that `doc` is a `kind` file of a version this Layerbot reads, and migrates it to the
 * current version. Returns the (possibly new) document value, or the problems.
 */
export function openEnvelope(
  doc: JsonDocument,
  kind: FileKind,
  file: string,
  migrations: Readonly<Record<number, Migration>> = MIGRATIONS[kind],
  current: number = CURRENT_VERSION[kind],
): { ok: true; value: Record<string, unknown> } | { ok: false; problems: FileProblem[] } {
  const at = (path: string) => {
    const p = doc.positionOf(path);
    return p ? { line: p.line, column: p.column } : {};
  };
  const problem = (path: string, message: string) => ({ ok: false as const, problems: [{ file, path, message, ...at(path) }] });
  const name = KIND_NAMES[kind];
  const value = doc.value;
  if (typeof value !== 'object' || value === null || Array.isArray(value)) {
    return problem('$', `expected a Layerbot ${name}: an object {"format": "${FORMATS[kind]}", "version": ${current}, ...}, found ${describeFound(value)}`);
  }
  const record = value as Record<string, unknown>;
  const format = record.format;
  if (format !== FORMATS[kind]) {
    if (format === undefined) return problem('$', `missing field "format": a ${name} file starts with "format": "${FORMATS[kind]}"`);
    const other = kindOfFormat(format);
    if (other) {
      return problem('$.format', `this file is a Layerbot ${KIND_NAMES[other]}, not a ${name}; open it as a ${KIND_NAMES[other]}`);
    }
    return problem('$.format', `expected "${FORMATS[kind]}" (this should be a Layerbot ${name} file), found ${describeFound(format)}`);
  }
  const version = record.version;
  if (version === undefined) return problem('$', `missing field "version": expected "version": ${current}`);
  if (typeof version !== 'number' || !Number.isInteger(version) || version < 1) {
    return problem('$.version', `expected a whole number from 1 to ${current}, found ${describeFound(version)}`);
  }
  if (version > current) {
    return problem(
      '$.version',
      `this ${name} was made by a newer Layerbot (format version ${version}; this Layerbot reads versions up to ${current}); update Layerbot to open it`,
    );
  }
  let migrated = record;
  for (let v = version; v < current; v++) {
    const step = migrations[v];
    if (!step) return problem('$.version', `cannot read version ${version} ${name} files: no way to upgrade from version ${v}`);
    migrated = { ...step(migrated), version: v + 1 };
  }
  return { ok: true, value: migrated };
}
