/** A light shape check of commands arriving at the Worker (the page is trusted; bugs are not). */
import type { EngineCommand } from './protocol';

const TYPES = new Set<EngineCommand['type']>(['load', 'step', 'run', 'speed', 'stop', 'reset', 'editWorld', 'arcs', 'ping', 'restore']);

export function isEngineCommand(v: unknown): v is EngineCommand {
  if (typeof v !== 'object' || v === null) return false;
  const c = v as Record<string, unknown>;
  if (!TYPES.has(c.type as EngineCommand['type'])) return false;
  switch (c.type) {
    case 'load':
      return typeof c.world === 'object' && c.world !== null && (c.controller === null || typeof c.controller === 'object') && typeof c.bodies === 'object' && c.bodies !== null;
    case 'run':
      return typeof c.speed === 'number' && typeof c.maxTicks === 'number';
    case 'speed':
      return typeof c.speed === 'number';
    case 'editWorld':
      return typeof c.edit === 'object' && c.edit !== null;
    case 'arcs':
      return typeof c.id === 'number' && typeof c.tick === 'number';
    case 'ping':
      return typeof c.id === 'number';
    case 'restore':
      return (
        typeof c.world === 'object' && c.world !== null && typeof c.controller === 'object' && c.controller !== null && typeof c.bodies === 'object' &&
        c.bodies !== null && typeof c.upTo === 'number' && typeof c.known === 'number' && typeof c.generation === 'number' && Array.isArray(c.edits)
      );
    default:
      return true;
  }
}
