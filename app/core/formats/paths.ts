/** JSON paths (`$.layers[1].name`) as problems name places in a file. */

/** A step into a JSON value: an object key or an array index. */
export type PathStep = string | number;

const SIMPLE_KEY = /^[A-Za-z_$][A-Za-z0-9_$]*$/;

/** Appends one step to a JSON path: `.key`, `["odd key"]` or `[3]`. */
export function childPath(path: string, step: PathStep): string {
  if (typeof step === 'number') return `${path}[${step}]`;
  return SIMPLE_KEY.test(step) ? `${path}.${step}` : `${path}[${JSON.stringify(step)}]`;
}

/** A JSON path from the root through `steps`. */
export function jsonPath(steps: readonly PathStep[]): string {
  return steps.reduce<string>(childPath, '$');
}

/**
 * The steps of a JSON Pointer (as Ajv reports `instancePath`), with array indices as numbers:
 * the data decides, since `/0` may be an index or an object key named "0".
 */
export function pointerSteps(pointer: string, data: unknown): PathStep[] {
  if (pointer === '') return [];
  const steps: PathStep[] = [];
  let here: unknown = data;
  for (const raw of pointer.slice(1).split('/')) {
    const key = raw.replace(/~1/g, '/').replace(/~0/g, '~');
    if (Array.isArray(here) && /^\d+$/.test(key)) {
      steps.push(Number(key));
      here = here[Number(key)];
    } else {
      steps.push(key);
      here = typeof here === 'object' && here !== null ? (here as Record<string, unknown>)[key] : undefined;
    }
  }
  return steps;
}
