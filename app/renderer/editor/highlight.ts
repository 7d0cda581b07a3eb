/**
 * A small JavaScript tokenizer for the Code pane's colouring: comments, strings, numbers,
 * keywords, the names of the sandbox's API, and everything else. Concatenating the tokens' text
 * gives the input back exactly.
 */
import { RESERVED_NAMES } from '../../core/sandbox/api';

export type TokenKind = 'comment' | 'string' | 'number' | 'keyword' | 'api' | 'text';

export interface Token {
  readonly kind: TokenKind;
  readonly text: string;
}

const KEYWORDS = new Set(
  'var function return if else for while do break continue new typeof in of null true false undefined this switch case default throw try catch finally instanceof delete void'.split(' '),
);
const API_NAMES = new Set<string>(RESERVED_NAMES);

const PATTERN = /(\/\/[^\n]*|\/\*[\s\S]*?\*\/)|('(?:[^'\\\n]|\\.)*'?|"(?:[^"\\\n]|\\.)*"?)|(\b\d+(?:\.\d+)?(?:[eE][+-]?\d+)?\b)|([A-Za-z_$][\w$]*)/g;

export function tokenize(code: string): Token[] {
  const out: Token[] = [];
  let last = 0;
  const push = (kind: TokenKind, text: string) => {
    if (!text) return;
    const prev = out[out.length - 1];
    if (prev && prev.kind === kind && kind === 'text') out[out.length - 1] = { kind, text: prev.text + text };
    else out.push({ kind, text });
  };
  for (const m of code.matchAll(PATTERN)) {
    push('text', code.slice(last, m.index));
    const [all, comment, str, num, word] = m;
    if (comment) push('comment', all);
    else if (str) push('string', all);
    else if (num) push('number', all);
    else if (word) push(KEYWORDS.has(word) ? 'keyword' : API_NAMES.has(word) ? 'api' : 'text', all);
    last = m.index + all.length;
  }
  push('text', code.slice(last));
  return out;
}
