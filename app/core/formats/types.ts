/** Results and problems shared by every file-format reader. */

/** One thing wrong with a file, said so that a teacher or student can fix it. */
export interface FileProblem {
  /** The file's name, as the caller gave it. */
  readonly file: string;
  /** Where in the file, as a JSON path: `$` is the whole file, e.g. `$.layers[1].functions[0].name`. */
  readonly path: string;
  /** What was expected, in plain words. */
  readonly message: string;
  /** 1-based line of the offending text, when known (for editors to jump to). */
  readonly line?: number;
  /** 1-based column of the offending text, when known. */
  readonly column?: number;
}

/** A value read from a file, or every problem that stopped it from being read. */
export type Result<T> = { readonly ok: true; readonly value: T } | { readonly ok: false; readonly problems: readonly FileProblem[] };

/** A successful result. */
export function ok<T>(value: T): Result<T> {
  return { ok: true, value };
}

/** A failed result; there is always at least one problem. */
export function fail<T>(problems: readonly FileProblem[]): Result<T> {
  return { ok: false, problems };
}

/** One line per problem, `file: $.path: message`, for printing on the command line. */
export function formatProblems(problems: readonly FileProblem[]): string {
  return problems.map((p) => `${p.file}: ${p.path}: ${p.message}`).join('\n');
}
