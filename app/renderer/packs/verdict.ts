/**
 * A verdict as the student reads it: a headline, then its reasons grouped by world (reasons about
 * the controller itself first, then each world's, the challenge world before the hidden variants),
 * each marked ✓ or ✗. DOM-free.
 */
import type { Reason, Verdict } from '../../core/packs/model';

export interface VerdictGroup {
  /** The world the reasons are about; null for reasons about the controller or the whole run. */
  readonly world: string | null;
  readonly reasons: readonly Reason[];
}

/** "Passed: all 16 checks hold" or "Not passed yet: 3 of 16 checks failed". */
export function headline(v: Verdict): string {
  const n = v.reasons.length;
  const failed = v.reasons.filter((r) => !r.passed).length;
  if (v.passed) return `Passed: ${n === 1 ? 'the check holds' : `all ${n} checks hold`}`;
  return `Not passed yet: ${failed} of ${n} ${n === 1 ? 'check' : 'checks'} failed`;
}

/** The reasons by world, in the order they first appear; world-less reasons first. */
export function verdictGroups(v: Verdict): VerdictGroup[] {
  const general = v.reasons.filter((r) => r.world === undefined);
  const byWorld = new Map<string, Reason[]>();
  for (const r of v.reasons) {
    if (r.world === undefined) continue;
    const list = byWorld.get(r.world) ?? [];
    list.push(r);
    byWorld.set(r.world, list);
  }
  const groups: VerdictGroup[] = [];
  if (general.length) groups.push({ world: null, reasons: general });
  for (const [world, reasons] of byWorld) groups.push({ world, reasons });
  return groups;
}

/** One reason as a line of text: "✓ no crash: no crash in 35 ticks". */
export function reasonLine(r: Reason): string {
  return `${r.passed ? '✓' : '✗'} ${r.criterion}: ${r.detail}`;
}

/** The whole verdict as plain text (for the clipboard and the tests). */
export function verdictText(v: Verdict): string {
  const lines = [headline(v)];
  for (const g of verdictGroups(v)) {
    if (g.world !== null) lines.push(`On ${g.world}:`);
    for (const r of g.reasons) lines.push(`${g.world !== null ? '  ' : ''}${reasonLine(r)}`);
  }
  return lines.join('\n');
}
