/**
 * A JSON reader for files people edit by hand. It accepts exactly what JSON.parse accepts, but
 * when the text is not JSON it says where (line and column) and what is wrong in plain words,
 * with the usual slips named: trailing commas, single quotes, comments, unquoted field names.
 * It also rejects a field written twice in one object (JSON.parse silently keeps the last one,
 * which hides mistakes), and remembers where each value starts so that later problems can point
 * editors at a line.
 */
import type { FileProblem, Result } from './types';
import { fail, ok } from './types';
import { childPath } from './paths';

/** A place in the text, 1-based. */
export interface TextPosition {
  readonly line: number;
  readonly column: number;
}

/** Parsed JSON with the position of every value, keyed by JSON path. */
export interface JsonDocument {
  readonly value: unknown;
  /** Where the value at a JSON path starts (for objects and arrays: their opening bracket). */
  positionOf(path: string): TextPosition | undefined;
}

/** Thrown inside the parser to stop at the first syntax error. */
class SyntaxProblem {
  constructor(
    readonly offset: number,
    readonly path: string,
    readonly message: string,
  ) {}
}

/** Beyond this depth paths stop growing (see Parser.child). */
const MAX_PATH_DEPTH = 64;

const NUMBER = /-?(?:0|[1-9]\d*)(?:\.\d+)?(?:[eE][+-]?\d+)?/y;
const WHITESPACE = /[ \t\n\r]*/y;

/** Reads JSON text; a syntax error or a repeated field is a problem with its line and column. */
export function parseJsonText(text: string, file: string): Result<JsonDocument> {
  // Editors on Windows may write a byte-order mark; JSON.parse would reject it, people cannot see it.
  const source = text.charCodeAt(0) === 0xfeff ? text.slice(1) : text;
  const shift = source.length === text.length ? 0 : 1;
  const lineStarts = [0];
  for (let i = 0; i < text.length; i++) if (text.charCodeAt(i) === 10) lineStarts.push(i + 1);
  const positionAt = (offset: number): TextPosition => {
    let lo = 0;
    let hi = lineStarts.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (lineStarts[mid] <= offset) lo = mid;
      else hi = mid - 1;
    }
    return { line: lo + 1, column: offset - lineStarts[lo] + 1 };
  };

  const offsets = new Map<string, number>();
  const duplicates: FileProblem[] = [];
  try {
    const value = new Parser(source, offsets, (path, key, first, again) => {
      const a = positionAt(first + shift);
      const b = positionAt(again + shift);
      duplicates.push({
        file,
        path,
        message: `the field "${key}" is written twice in this object (${a.line === b.line ? `both on line ${a.line}` : `on line ${a.line} and again on line ${b.line}`}); keep only one`,
        line: b.line,
        column: b.column,
      });
    }).document();
    if (duplicates.length) return fail(duplicates);
    return ok({
      value,
      positionOf(path: string) {
        const at = offsets.get(path);
        return at === undefined ? undefined : positionAt(at + shift);
      },
    });
  } catch (e) {
    if (e instanceof RangeError) return deepFallback(source, file);
    if (!(e instanceof SyntaxProblem)) throw e;
    const { line, column } = positionAt(e.offset + shift);
    return fail([{ file, path: e.path, message: `not valid JSON at line ${line}, column ${column}: ${e.message}`, line, column }]);
  }
}

/**
 * Nesting too deep for this parser's recursion (thousands of levels): JSON.parse copes, at the
 * price of positions, repeated-field checks and friendly syntax messages.
 */
function deepFallback(source: string, file: string): Result<JsonDocument> {
  try {
    const value: unknown = JSON.parse(source);
    return ok({ value, positionOf: () => undefined });
  } catch (e) {
    return fail([{ file, path: '$', message: `not valid JSON: ${e instanceof Error ? e.message : String(e)}` }]);
  }
}

type DuplicateKey = (path: string, key: string, firstOffset: number, againOffset: number) => void;

class Parser {
  private i = 0;

  constructor(
    private readonly s: string,
    private readonly offsets: Map<string, number>,
    private readonly onDuplicate: DuplicateKey,
  ) {}

  document(): unknown {
    this.space('$');
    if (this.i >= this.s.length) throw new SyntaxProblem(this.i, '$', 'the file is empty; expected a JSON object starting with {');
    const value = this.value('$');
    this.space('$');
    if (this.i < this.s.length) {
      throw new SyntaxProblem(this.i, '$', 'unexpected text after the end of the JSON value; the file should hold one object { ... } and nothing after its closing }');
    }
    return value;
  }

  /** Skips whitespace; comments are a common slip, so they get their own message. */
  private space(path: string): void {
    WHITESPACE.lastIndex = this.i;
    WHITESPACE.test(this.s);
    this.i = WHITESPACE.lastIndex;
    if (this.s.startsWith('//', this.i) || this.s.startsWith('/*', this.i)) {
      throw new SyntaxProblem(this.i, path, 'JSON does not allow comments; remove the comment (a "description" field can hold notes)');
    }
  }

  private depth = 0;

  /**
   * The path of a child value. Deep inside (Blockly bodies nest a level per block) the path stops
   * growing and positions are no longer recorded: nobody reads a path 500 levels deep, and long
   * paths at every level would cost memory quadratic in the depth. Line and column stay exact.
   */
  private child(path: string, step: string | number): string {
    return this.depth > MAX_PATH_DEPTH ? path : childPath(path, step);
  }

  private value(path: string): unknown {
    const c = this.s[this.i];
    if (this.depth <= MAX_PATH_DEPTH) this.offsets.set(path, this.i);
    switch (c) {
      case '{':
      case '[': {
        this.depth++;
        const v = c === '{' ? this.object(path) : this.array(path);
        this.depth--;
        return v;
      }
      case '"':
        return this.string(path);
      case 't':
        return this.word('true', true, path);
      case 'f':
        return this.word('false', false, path);
      case 'n':
        return this.word('null', null, path);
      case undefined:
        throw new SyntaxProblem(this.i, path, 'the file ends too early; expected a value');
      case "'":
        throw new SyntaxProblem(this.i, path, 'text must be in double quotes ("like this"), not single quotes');
      default:
        if (c === '-' || (c >= '0' && c <= '9')) return this.number(path);
        if (/[A-Za-z]/.test(c)) return this.word('', null, path);
        throw new SyntaxProblem(this.i, path, `expected a value (a number, "text" in double quotes, true, false, null, a list [...] or an object {...}), found ${this.found()}`);
    }
  }

  private object(path: string): Record<string, unknown> {
    const start = this.i;
    this.i++;
    const result: Record<string, unknown> = {};
    const keyAt = new Map<string, number>();
    this.space(path);
    if (this.s[this.i] === '}') {
      this.i++;
      return result;
    }
    for (;;) {
      const c = this.s[this.i];
      if (c === undefined) throw this.unclosed('object', '}', start, path);
      if (c !== '"') {
        if (c === '}') throw new SyntaxProblem(this.i, path, 'a comma before } is not allowed in JSON; remove the comma after the last field');
        if (c === "'") throw new SyntaxProblem(this.i, path, 'field names must be in double quotes ("name"), not single quotes');
        if (/[A-Za-z_$]/.test(c)) throw new SyntaxProblem(this.i, path, `field names must be in double quotes: write "${this.identifierHere()}"`);
        throw new SyntaxProblem(this.i, path, `expected a field name in double quotes, found ${this.found()}`);
      }
      const keyOffset = this.i;
      const key = this.string(path);
      const valuePath = this.child(path, key);
      const first = keyAt.get(key);
      if (first !== undefined) this.onDuplicate(valuePath, key, first, keyOffset);
      else keyAt.set(key, keyOffset);
      this.space(valuePath);
      if (this.s[this.i] !== ':') {
        if (this.i >= this.s.length) throw this.unclosed('object', '}', start, path);
        throw new SyntaxProblem(this.i, valuePath, `expected a colon : after the field name "${key}", found ${this.found()}`);
      }
      this.i++;
      this.space(valuePath);
      const value = this.value(valuePath);
      // Assigning "__proto__" would set the prototype instead of making a field.
      if (key === '__proto__') Object.defineProperty(result, key, { value, enumerable: true, writable: true, configurable: true });
      else result[key] = value;
      this.space(path);
      const next = this.s[this.i];
      if (next === ',') {
        this.i++;
        this.space(path);
        continue;
      }
      if (next === '}') {
        this.i++;
        return result;
      }
      if (next === undefined) throw this.unclosed('object', '}', start, path);
      if (next === '"') throw new SyntaxProblem(this.i, path, `a comma is missing after the value of "${key}"`);
      throw new SyntaxProblem(this.i, path, `expected a comma or } after the value of "${key}", found ${this.found()}`);
    }
  }

  private array(path: string): unknown[] {
    const start = this.i;
    this.i++;
    const result: unknown[] = [];
    this.space(path);
    if (this.s[this.i] === ']') {
      this.i++;
      return result;
    }
    for (;;) {
      const itemPath = this.child(path, result.length);
      if (this.s[this.i] === ']') throw new SyntaxProblem(this.i, path, 'a comma before ] is not allowed in JSON; remove the comma after the last item');
      if (this.s[this.i] === ',') throw new SyntaxProblem(this.i, itemPath, 'expected an item before this comma (two commas in a row?)');
      if (this.i >= this.s.length) throw this.unclosed('list', ']', start, path);
      result.push(this.value(itemPath));
      this.space(path);
      const next = this.s[this.i];
      if (next === ',') {
        this.i++;
        this.space(path);
        continue;
      }
      if (next === ']') {
        this.i++;
        return result;
      }
      if (next === undefined) throw this.unclosed('list', ']', start, path);
      throw new SyntaxProblem(this.i, itemPath, `expected a comma or ] after this item, found ${this.found()}${next === '"' || next === '{' || next === '[' || /[-\d]/.test(next) ? ' (a comma is missing?)' : ''}`);
    }
  }

  private string(path: string): string {
    const start = this.i;
    let j = this.i + 1;
    let simple = true;
    for (;;) {
      const c = this.s.charCodeAt(j);
      if (Number.isNaN(c)) throw new SyntaxProblem(start, path, 'this text has no closing double quote "');
      if (c === 0x22) break;
      if (c < 0x20) {
        if (c === 10 || c === 13) throw new SyntaxProblem(start, path, 'this text has no closing double quote " on its line (a line break inside text must be written as \\n)');
        throw new SyntaxProblem(j, path, 'a control character (such as a tab) inside text must be written with a backslash, e.g. \\t');
      }
      if (c === 0x5c) {
        simple = false;
        const e = this.s[j + 1];
        if (e === 'u') {
          if (!/^[0-9a-fA-F]{4}$/.test(this.s.slice(j + 2, j + 6))) throw new SyntaxProblem(j, path, '\\u must be followed by four hexadecimal digits');
          j += 6;
          continue;
        }
        if (e === undefined || !'"\\/bfnrt'.includes(e)) {
          throw new SyntaxProblem(j, path, `"\\${e ?? ''}" is not a valid escape in JSON text; write a backslash as \\\\`);
        }
        j += 2;
        continue;
      }
      j++;
    }
    this.i = j + 1;
    const raw = this.s.slice(start, j + 1);
    return simple ? raw.slice(1, -1) : (JSON.parse(raw) as string);
  }

  private number(path: string): number {
    NUMBER.lastIndex = this.i;
    const m = NUMBER.exec(this.s);
    const after = m ? this.i + m[0].length : this.i;
    if (!m || m[0] === '-' || /[\w.]/.test(this.s[after] ?? '')) {
      const word = /^[-+\w.]+/.exec(this.s.slice(this.i))?.[0] ?? this.s[this.i];
      throw new SyntaxProblem(this.i, path, `"${word}" is not a valid JSON number (numbers look like 12, -3.5 or 1e6: no leading zeros, no trailing dot)`);
    }
    this.i = after;
    return Number(m[0]);
  }

  private word<T>(word: string, value: T, path: string): T {
    if (word && this.s.startsWith(word, this.i) && !/\w/.test(this.s[this.i + word.length] ?? '')) {
      this.i += word.length;
      return value;
    }
    const found = /^\w+/.exec(this.s.slice(this.i))?.[0] ?? this.s[this.i];
    throw new SyntaxProblem(this.i, path, `expected a value, found ${JSON.stringify(found)} (text must be in double quotes; true, false and null are written in lower case)`);
  }

  private unclosed(what: string, close: string, start: number, path: string): SyntaxProblem {
    return new SyntaxProblem(start, path, `this ${what} is never closed: the file ends before its ${close}`);
  }

  private identifierHere(): string {
    return /^[A-Za-z_$][\w$]*/.exec(this.s.slice(this.i))?.[0] ?? '';
  }

  private found(): string {
    const c = this.s[this.i];
    if (c === undefined) return 'the end of the file';
    const word = /^[A-Za-z_]\w*/.exec(this.s.slice(this.i))?.[0];
    if (word) return JSON.stringify(word);
    return JSON.stringify(c);
  }
}
