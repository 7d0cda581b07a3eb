/**
 * Challenge packs as the engine sees them, once read and checked: challenges (a world, a starter
 * controller, locks, toolbox, success criteria, hints), submissions (a student's controllers by
 * challenge id) and verdicts (what passed and what did not, in words).
 */
import type { ControllerSpec } from '../controller/model';
import type { WorldSpec } from '../world/world';

/**
 * The toolbox categories a challenge may offer, by name. They mirror blocks/toolbox.ts
 * (CATEGORY_NAMES), which app/core cannot import; a unit test keeps the two lists equal.
 */
export const TOOLBOX_CATEGORIES = ['Inputs', 'Logic', 'Loops', 'Math', 'Text', 'Lists', 'Geometry', 'World', 'Grid', 'Variables', 'Helpers'] as const;
export type ToolboxCategory = (typeof TOOLBOX_CATEGORIES)[number];

/** The most ticks a challenge run takes when the pack does not say. */
export const DEFAULT_CHALLENGE_TICKS = 2000;

/** A locked part of the starter: a whole layer, or one function of a layer. Visible, not editable. */
export type Lock = { readonly layer: string; readonly function?: string };

/** One success criterion; a challenge combines several, and passes when all pass. */
export type Criterion =
  /**
   * Reach goals: `goals` (default: the world's plan). Order "plan": each in turn, the way the
   * world tracks its plan (a goal counts only once the one before it was reached); "any": each at
   * some tick, in any order.
   */
  | { readonly kind: 'reachGoals'; readonly goals?: readonly string[]; readonly order: 'plan' | 'any' }
  /** Every goal the challenge asks for (its reachGoals criteria, else the plan) is reached by tick N. */
  | { readonly kind: 'withinTicks'; readonly ticks: number }
  | { readonly kind: 'noCrash' }
  | { readonly kind: 'noError' }
  /** At most M blocks in the functions the student may edit ("editable") or in the whole controller. */
  | { readonly kind: 'maxBlocks'; readonly blocks: number; readonly scope: 'editable' | 'all' }
  /** A function of this name must exist in the layer of this name. */
  | { readonly kind: 'hasFunction'; readonly layer: string; readonly function: string }
  /** The controller must also pass on these worlds (hidden from students: no hard-coded paths). */
  | { readonly kind: 'variants'; readonly worlds: readonly WorldSpec[] };

export type CriterionKind = Criterion['kind'];

export interface Challenge {
  /** Unique within the pack; submissions name challenges by it. */
  readonly id: string;
  readonly title: string;
  readonly description: string;
  readonly world: WorldSpec;
  readonly starter: ControllerSpec;
  readonly locked: readonly Lock[];
  /** The toolbox categories offered; absent means all of them. */
  readonly toolbox?: readonly ToolboxCategory[];
  readonly criteria: readonly Criterion[];
  /** Revealed one at a time, in order. */
  readonly hints: readonly string[];
  /** The longest a run may take, in ticks. */
  readonly maxTicks: number;
}

export interface Pack {
  readonly title: string;
  readonly author: string;
  readonly description: string;
  readonly challenges: readonly Challenge[];
}

/** One student's work on a pack: a controller per challenge id (challenges left out were not attempted). */
export interface Submission {
  /** The title of the pack the work is for. */
  readonly pack: string;
  readonly student?: string;
  readonly controllers: Readonly<Record<string, ControllerSpec>>;
}

/** One line of a verdict: a criterion (on one world, when there are variants), whether it held, and why. */
export interface Reason {
  /** What was asked, in short: "reach o109, storage in plan order", "no crash", "locked parts unchanged". */
  readonly criterion: string;
  /** Which world the line is about, when the challenge has variants. */
  readonly world?: string;
  readonly passed: boolean;
  /** What happened, specifically: "reached o103 at tick 140", "crashed at tick 171 ...". */
  readonly detail: string;
}

/** The verdict on one challenge: passed when every reason passed. */
export interface Verdict {
  readonly passed: boolean;
  readonly reasons: readonly Reason[];
}

/** A challenge's verdict with the challenge it is for. */
export interface ChallengeVerdict extends Verdict {
  readonly challenge: string;
  readonly title: string;
}
