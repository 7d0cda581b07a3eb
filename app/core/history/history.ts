/**
 * Every tick of a run, kept so any tick can be shown again. Records are frozen and share every
 * value that did not change, so memory grows with what changes, not with the size of the values.
 * Seeking is an array index. Nothing is thinned out; what bounds memory is described in
 * app/core/CONTEXT.md ("What the history keeps").
 */
import type { TickRecord } from '../session/types';

export class History {
  private records: TickRecord[] = [];

  /** Starts over with the given tick-0 record. */
  constructor(first: TickRecord) {
    this.records.push(first);
  }

  /** Number of ticks recorded, tick 0 included. */
  get length(): number {
    return this.records.length;
  }

  /** The newest record. */
  get latest(): TickRecord {
    return this.records[this.records.length - 1];
  }

  /** The record of a tick; throws a RangeError for a tick that was not recorded. */
  at(tick: number): TickRecord {
    const r = this.records[tick];
    if (!r) throw new RangeError(`Tick ${tick} is not in the history (it holds ticks 0 to ${this.records.length - 1}).`);
    return r;
  }

  /** The record of a tick, or undefined. */
  get(tick: number): TickRecord | undefined {
    return this.records[tick];
  }

  /** Appends the next tick's record. */
  push(record: TickRecord): void {
    if (record.tick !== this.records.length) throw new RangeError(`Expected tick ${this.records.length}, got ${record.tick}.`);
    this.records.push(record);
  }

  /** Replaces the newest record (a world edit recorded at the current tick). */
  replaceLatest(record: TickRecord): void {
    if (record.tick !== this.latest.tick) throw new RangeError(`Expected tick ${this.latest.tick}, got ${record.tick}.`);
    this.records[this.records.length - 1] = record;
  }

  /** Iterates over the records from tick `from` on. */
  *slice(from = 0, to = this.records.length): IterableIterator<TickRecord> {
    for (let t = Math.max(0, from); t < Math.min(to, this.records.length); t++) yield this.records[t];
  }
}
