/**
 * Shares equal small lists between a session's outputs: a grid of cells that a function builds
 * anew (a value-iteration replan makes 22,500 lists of five numbers) holds far fewer distinct cells
 * than cells (about 2,000 of 22,500 on a 150 x 150 grid), and the history keeps every replan. Each
 * distinct cell is kept once, so a replan costs a tenth of the memory.
 *
 * Only lists of plain values are shared (finite numbers other than -0, texts, booleans, null):
 * for them an equal list behaves the same in every way student code can see, except `===` between
 * two cells, which both engines then answer alike (the reference engine keeps one object per
 * native). Values are frozen; lists holding shared cells are rebuilt (frozen) when one changes.
 */

/** Longest list shared as a cell. */
const MAX_CELL = 16;
/** Shortest list whose cells are shared. */
const MIN_ROW = 16;
/** Most cells remembered; past it, the table starts over (sharing is an optimisation only). */
const MAX_ENTRIES = 200_000;

export class CellInterner {
  private cells = new Map<string, readonly unknown[]>();

  /** Drops every remembered cell (a reset). */
  clear(): void {
    this.cells = new Map();
  }

  /**
   * `value` with its cells replaced by equal cells met before; the same object when none was.
   * Cells are shared only inside lists of at least MIN_ROW entries (the rows of a grid): a lone
   * point or move, new every tick, would only fill the table.
   */
  intern(value: unknown): unknown {
    if (!Array.isArray(value)) return value;
    const row = value.length >= MIN_ROW;
    let copy: unknown[] | null = null;
    for (let i = 0; i < value.length; i++) {
      const x: unknown = value[i];
      let y = x;
      if (Array.isArray(x)) {
        const key = row ? cellKey(x) : null;
        y = key !== null ? this.cell(x, key) : this.intern(x);
      }
      if (y !== x && copy === null) copy = value.slice(0, i);
      if (copy !== null) copy.push(y);
    }
    return copy === null ? value : Object.freeze(copy);
  }

  private cell(value: readonly unknown[], key: string): readonly unknown[] {
    const known = this.cells.get(key);
    if (known !== undefined) return known;
    if (this.cells.size >= MAX_ENTRIES) this.cells = new Map();
    this.cells.set(key, value);
    return value;
  }
}

/** A key telling equal cells apart from every other, or null when `a` is not a cell to share. */
function cellKey(a: readonly unknown[]): string | null {
  if (a.length === 0 || a.length > MAX_CELL || !Object.isFrozen(a)) return null;
  let key = '';
  for (let i = 0; i < a.length; i++) {
    const x: unknown = a[i];
    if (typeof x === 'number') {
      if (!Number.isFinite(x) || Object.is(x, -0)) return null;
      key += `n${x},`;
    } else if (typeof x === 'boolean') key += x ? 't,' : 'f,';
    else if (x === null) key += 'z,';
    else if (typeof x === 'string') key += `s${JSON.stringify(x)},`;
    else return null;
  }
  return key;
}
