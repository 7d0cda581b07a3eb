/**
 * A dropdown whose options are computed from the workspace (the function's inputs, its layer
 * variables, the controller's arc sources) and that accepts any value, so a block loads even when
 * the name it refers to is defined later in the file or is gone. A missing name is shown as such
 * and reported when the code is generated, instead of being silently replaced.
 *
 * This file has no side effects.
 */
import * as Blockly from 'blockly/core';

export type NameOptions = (block: Blockly.Block | null) => [string, string][];

/** Option providers by the name used in block JSON (`"options": "inputs"`). */
const providers = new Map<string, NameOptions>();

export function setNameOptions(kind: string, provider: NameOptions): void {
  providers.set(kind, provider);
}

export const FIELD_NAME_DROPDOWN = 'lb_field_name_dropdown';

export class FieldNameDropdown extends Blockly.FieldDropdown {
  constructor(readonly kind: string) {
    super(function (this: Blockly.FieldDropdown): Blockly.MenuOption[] {
      const field = this as FieldNameDropdown;
      const provider = providers.get(field.kind);
      const options: [string, string][] = provider ? provider(field.getSourceBlock()) : [];
      const value = field.getValue();
      if (value && !options.some((o) => o[1] === value)) options.push([`${value} (missing)`, value]);
      if (options.length === 0) options.push(['(none)', '']);
      return options;
    });
  }

  /**
   * The options depend on the workspace, which changes (a block loading later defines the name):
   * recompute them when the value changes, so the label matches the value.
   */
  protected override doValueUpdate_(newValue: string): void {
    super.doValueUpdate_(newValue);
    this.getOptions(false);
    super.doValueUpdate_(newValue);
  }

  /** Recomputes the options and redraws the label if it changed (a name appeared or went). */
  refresh(): void {
    const value = this.getValue();
    if (value === null) return;
    const before = this.getText();
    this.getOptions(false);
    super.doValueUpdate_(value);
    if (this.getText() !== before) this.forceRerender();
  }

  /** Any text is accepted: the name is checked when code is generated. */
  protected override doClassValidation_(newValue?: string): string | null {
    return typeof newValue === 'string' ? newValue : null;
  }

  static override fromJson(options: Blockly.FieldDropdownFromJsonConfig & { options?: unknown; kind?: string }): FieldNameDropdown {
    return new FieldNameDropdown(String(options.kind ?? ''));
  }
}
