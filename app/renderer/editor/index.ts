/**
 * The controller editor's panes: Blocks (layers, functions and their bodies in Blockly, or a
 * function's JavaScript text) and Code (a function's JavaScript as the engine runs it). They share
 * one `EditorSession`. See app/renderer/CONTEXT.md.
 */
import './editor.css';
import type { ControllerPane } from '../panes/types';
import { BlocksPane } from './blocks-pane';
import { CodePane } from './code-pane';
import type { FunctionRef } from './model';
import { EditorSession } from './session';

let latest: BlocksPane | null = null;

/** The editor's panes, in tab order. */
export function editorPanes(): ControllerPane[] {
  const session = new EditorSession();
  const blocks = new BlocksPane(session);
  latest = blocks;
  return [blocks, new CodePane(session)];
}

/** For the browser tests (app/test-hooks.ts): what the Blocks pane shows. */
export function editorTestState(): ReturnType<BlocksPane['testState']> | null {
  return latest?.testState() ?? null;
}

/** For the browser tests: the block id of a function in the controller workspace. */
export function editorFunctionBlockId(ref: FunctionRef): string | null {
  return latest?.testFunctionBlockId(ref) ?? null;
}
