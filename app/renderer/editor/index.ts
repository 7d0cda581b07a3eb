/**
 * PLACEHOLDER until the Blockly controller editor lands: the panes the editor engineer provides.
 * Replace this file's body (keep the export) with the real Blocks and Code panes.
 */
import type { ControllerPane } from '../panes/types';
import { OutlinePane } from './outline';

/** The editor's panes, in tab order. */
export function editorPanes(): ControllerPane[] {
  return [new OutlinePane('blocks', 'Blocks'), new OutlinePane('code', 'Code')];
}
