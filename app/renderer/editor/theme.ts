/**
 * Blockly's look, from the page's theme (styles/theme.css): the workspace, toolbox and flyout
 * take the app's surface colours, and the high-contrast theme darkens the blocks so their white
 * text stays readable (editor.css adds white outlines). Follows the theme switch
 * (`data-theme` on the root element).
 */
import * as Blockly from 'blockly/core';

const css = (name: string, fallback: string): string => getComputedStyle(document.documentElement).getPropertyValue(name).trim() || fallback;

export const isContrast = (): boolean => document.documentElement.dataset.theme === 'contrast';

let serial = 0;

/** A Blockly theme with the page's current colours. */
export function pageTheme(): Blockly.Theme {
  const contrast = isContrast();
  // Block colours come from hues; the value sets how dark they are.
  Blockly.utils.colour.setHsvSaturation(contrast ? 0.7 : 0.45);
  Blockly.utils.colour.setHsvValue(contrast ? 0.42 : 0.66);
  return Blockly.Theme.defineTheme(`layerbot-${contrast ? 'contrast' : 'light'}-${++serial}`, {
    name: `layerbot-${contrast ? 'contrast' : 'light'}`,
    base: Blockly.Themes.Classic,
    componentStyles: {
      workspaceBackgroundColour: css('--surface-2', '#f6f8fb'),
      toolboxBackgroundColour: css('--surface', '#ffffff'),
      toolboxForegroundColour: css('--text', '#1c2333'),
      flyoutBackgroundColour: css('--surface-3', '#e9edf3'),
      flyoutForegroundColour: css('--text', '#1c2333'),
      flyoutOpacity: 1,
      scrollbarColour: css('--border-strong', '#c4ccd8'),
      scrollbarOpacity: contrast ? 1 : 0.7,
      insertionMarkerColour: contrast ? '#ffffff' : '#000000',
      insertionMarkerOpacity: 0.3,
      markerColour: css('--accent', '#4f46e5'),
      cursorColour: css('--accent', '#4f46e5'),
      selectedGlowColour: css('--accent', '#4f46e5'),
    },
    fontStyle: { family: "Inter, 'Segoe UI', system-ui, -apple-system, Roboto, 'Helvetica Neue', Arial, sans-serif", weight: '600', size: 10.5 },
  });
}

/** Re-colours every block of the workspaces (after the hue-to-colour settings changed). */
export function recolour(workspaces: readonly Blockly.WorkspaceSvg[]): void {
  const theme = pageTheme();
  for (const ws of workspaces) {
    ws.setTheme(theme);
    for (const block of ws.getAllBlocks(false)) {
      const hue = block.getHue();
      if (hue !== null) block.setColour(hue);
    }
    const flyout = ws.getFlyout();
    flyout?.getWorkspace().getAllBlocks(false).forEach((b) => {
      const hue = b.getHue();
      if (hue !== null) b.setColour(hue);
    });
  }
}

/** Calls `fn` whenever the page's theme switches. */
export function onThemeChange(fn: () => void): void {
  new MutationObserver(() => fn()).observe(document.documentElement, { attributes: true, attributeFilter: ['data-theme'] });
}
