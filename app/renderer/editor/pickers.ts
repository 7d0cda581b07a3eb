/** The function pickers of the Blocks and Code panes: one option group per layer. */
import type { ControllerSpec } from '../../core/controller/model';
import { el } from '../panels/dom';
import type { FunctionRef } from './model';

/** A picker option's value for a function (layer and name, which neither may contain). */
export const functionValue = (ref: FunctionRef): string => `${ref.layer}\u0000${ref.fn}`;

/** An option group per layer, an option per function. */
export function functionOptionGroups(spec: ControllerSpec | null): HTMLOptGroupElement[] {
  return (spec?.layers ?? []).map((layer) => {
    const group = el('optgroup');
    group.label = layer.name;
    for (const fn of layer.functions) {
      const o = el('option', '', fn.name);
      o.value = functionValue({ layer: layer.name, fn: fn.name });
      group.appendChild(o);
    }
    return group;
  });
}
