/** Short text for an arc's value on the diagram (a chip has room for about 14 characters). */
import { formatValue } from '../../core/values';

function num(n: number): string {
  if (!Number.isFinite(n)) return String(n);
  if (Number.isInteger(n)) return String(n);
  const a = Math.abs(n);
  const digits = a >= 100 ? 0 : a >= 10 ? 1 : 2;
  return String(Number(n.toFixed(digits)));
}

function json(v: unknown): string {
  try {
    return JSON.stringify(v, (_k, x: unknown) => (typeof x === 'number' ? Number(num(x)) : x)) ?? String(v);
  } catch {
    return String(v);
  }
}

export function shortArcValue(v: unknown, max = 14): string {
  if (v === undefined) return '—';
  if (typeof v === 'number') return num(v);
  if (typeof v === 'boolean' || v === null) return String(v);
  if (typeof v === 'string') {
    const s = JSON.stringify(v);
    return s.length > max ? `${s.slice(0, max - 2)}…"` : s;
  }
  const text = json(v);
  if (text.length <= max) return text;
  if (Array.isArray(v)) {
    if (v.length > 0 && v.every((r) => Array.isArray(r) && r.length > 0 && r.length === (v[0] as unknown[]).length)) {
      return `grid ${v.length}×${(v[0] as unknown[]).length}`;
    }
    return `[${v.length} item${v.length === 1 ? '' : 's'}]`;
  }
  if (typeof v === 'object') {
    const keys = Object.keys(v as object);
    const list = `{${keys.join(', ')}}`;
    return list.length <= max ? list : `{${keys.length} fields}`;
  }
  return text.slice(0, max - 1) + '…';
}

/** The full value for a tooltip (long values are cut, so a tooltip stays a tooltip). */
export function fullArcValue(v: unknown): string {
  return formatValue(v, 1500);
}
