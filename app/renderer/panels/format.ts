/** Short, readable text for arc values in the arc table. */
import { formatValue } from '../../core/values';

export function shortValue(v: unknown): string {
  if (v === undefined) return '—';
  if (typeof v === 'number') return Number.isInteger(v) ? String(v) : String(Math.round(v * 1000) / 1000);
  if (Array.isArray(v) && v.length > 0 && Array.isArray(v[0])) {
    const inner = (v[0] as unknown[]).length;
    const deep = Array.isArray((v[0] as unknown[])[0]) ? ` × ${((v[0] as unknown[])[0] as unknown[]).length}` : '';
    return `grid ${v.length} × ${inner}${deep}`;
  }
  return formatValue(v, 140);
}
