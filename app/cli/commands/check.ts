/** `layerbot check FILE...`: validates worlds, controllers and packs and explains every problem. */
import { detectFormat } from '../../core/formats';
import { parsePack, parseSubmission } from '../../core/packs';
import { readTextFile } from '../files';
import { checkCompiles, InputError, loadController, loadWorld } from '../load';

/** Checks each file; returns 0 when all are valid, 2 otherwise. */
export function checkCommand(files: readonly string[], out: (s: string) => void, err: (s: string) => void): number {
  let bad = 0;
  for (const file of files) {
    try {
      const kind = kindOf(file);
      if (kind === 'world') loadWorld(file);
      else if (kind === 'controller') checkCompiles(loadController(file), file);
      else {
        const text = readTextFile(file);
        const parsed = kind === 'pack' ? parsePack(text, file) : parseSubmission(text, file);
        if (!parsed.ok) throw new InputError(parsed.problems.map((p) => `${p.file}: ${p.path}: ${p.message}`).join('\n'));
      }
      out(`${file}: OK (${kind})`);
    } catch (e) {
      bad++;
      err(e instanceof InputError ? e.message : `${file}: ${e instanceof Error ? e.message : String(e)}`);
    }
  }
  if (files.length > 1) out(bad ? `${bad} of ${files.length} files have problems.` : `All ${files.length} files are valid.`);
  return bad ? 2 : 0;
}

type Kind = 'world' | 'controller' | 'pack' | 'submission';

function kindOf(file: string): Kind {
  let text: string;
  try {
    text = readTextFile(file);
  } catch (e) {
    throw new InputError(e instanceof Error ? e.message : String(e));
  }
  const format = declaredFormat(text) ?? detectFormat(text);
  if (format === 'world' || /\.world\.json$/i.test(file)) return 'world';
  if (format === 'controller' || /\.controller\.json$/i.test(file)) return 'controller';
  if (format === 'pack' || /\.pack\.json$/i.test(file)) return 'pack';
  if (format === 'submission' || /\.submission\.json$/i.test(file)) return 'submission';
  throw new InputError(
    `${file}: $.format: expected "layerbot-world", "layerbot-controller", "layerbot-pack" or "layerbot-submission"; cannot tell what kind of file this is.`,
  );
}

/** The kind a file's "format" field declares, read without validating anything else. */
function declaredFormat(text: string): Kind | null {
  const m = /"format"\s*:\s*"layerbot-(world|controller|pack|submission)"/.exec(text.slice(0, 2000));
  return m ? (m[1] as Kind) : null;
}
