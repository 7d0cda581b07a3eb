/** `layerbot check FILE...`: validates worlds, controllers and packs and explains every problem. */
import { detectFormat } from '../../core/formats';
import { readTextFile } from '../files';
import { checkCompiles, InputError, loadController, loadWorld } from '../load';

/** Checks each file; returns 0 when all are valid, 2 otherwise. */
export function checkCommand(files: readonly string[], out: (s: string) => void, err: (s: string) => void): number {
  let bad = 0;
  for (const file of files) {
    try {
      const kind = kindOf(file);
      if (kind === 'world') loadWorld(file);
      else checkCompiles(loadController(file), file);
      out(`${file}: OK (${kind})`);
    } catch (e) {
      bad++;
      err(e instanceof InputError ? e.message : `${file}: ${e instanceof Error ? e.message : String(e)}`);
    }
  }
  if (files.length > 1) out(bad ? `${bad} of ${files.length} files have problems.` : `All ${files.length} files are valid.`);
  return bad ? 2 : 0;
}

function kindOf(file: string): 'world' | 'controller' {
  let text: string;
  try {
    text = readTextFile(file);
  } catch (e) {
    throw new InputError(e instanceof Error ? e.message : String(e));
  }
  const format = detectFormat(text);
  if (format === 'world' || /\.world\.json$/i.test(file)) return 'world';
  if (format === 'controller' || /\.controller\.json$/i.test(file)) return 'controller';
  throw new InputError(`${file}: $.format: expected "layerbot-world" or "layerbot-controller"; cannot tell what kind of file this is.`);
}
