/**
 * Seeded random sources: one independent stream per source, one value per tick. The same seed
 * gives the same values after a reset, so a run with random inputs replays exactly.
 */
import { unsafeUniformIntDistribution, xoroshiro128plus } from 'pure-rand';
import type { RandomGenerator } from 'pure-rand';
import type { RandomSourceSpec } from '../controller/model';

const INT_MIN = -(2 ** 31);
const INT_MAX = 2 ** 31 - 1;
const LONG_LIMIT = Number.MAX_SAFE_INTEGER;

/** Folds any integer seed (up to 2^53) into the 32 bits the generator takes, keeping its high part. */
function seed32(seed: number): number {
  const s = Math.trunc(seed);
  return (Math.floor(s / 2 ** 32) * 0x9e3779b1 + (s >>> 0)) | 0;
}

/** A stream of values of one random source. */
export class RandomStream {
  private rng: RandomGenerator;

  constructor(
    readonly spec: RandomSourceSpec,
    seed: number = spec.seed,
  ) {
    this.rng = xoroshiro128plus(seed32(seed));
  }

  /** The next value, as the source's type describes. */
  next(): boolean | number {
    switch (this.spec.type) {
      case 'boolean':
        return this.int(0, 1) === 1;
      case 'double':
        return (this.int(0, 2 ** 26 - 1) * 2 ** 27 + this.int(0, 2 ** 27 - 1)) / 2 ** 53;
      case 'float':
        return this.int(0, 2 ** 24 - 1) / 2 ** 24;
      case 'int':
        return this.int(this.spec.min ?? INT_MIN, this.spec.max ?? INT_MAX);
      case 'long':
        return this.int(this.spec.min ?? -LONG_LIMIT, this.spec.max ?? LONG_LIMIT);
      case 'gaussian':
        return this.gaussian();
    }
  }

  private int(min: number, max: number): number {
    return unsafeUniformIntDistribution(Math.ceil(min), Math.floor(max), this.rng);
  }

  /** Box-Muller: mean 0, standard deviation 1. */
  private gaussian(): number {
    const u = 1 - this.int(0, 2 ** 30) / 2 ** 30; // (0, 1]
    const v = this.int(0, 2 ** 30) / 2 ** 30;
    return Math.sqrt(-2 * Math.log(u)) * Math.cos(2 * Math.PI * v);
  }
}

/**
 * The streams of a controller's sources. With an override seed (the CLI's `--seed`), source i
 * uses seed + i, so sources stay independent of each other.
 */
export function createStreams(sources: readonly RandomSourceSpec[], overrideSeed?: number): RandomStream[] {
  return sources.map((s, i) => new RandomStream(s, overrideSeed === undefined ? s.seed : overrideSeed + i));
}
