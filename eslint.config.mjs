// Lint keeps the architecture's boundaries visible: each rule says why when it fires.
import js from '@eslint/js';
import tseslint from 'typescript-eslint';

const coreBoundary =
  'app/core is the DOM-free engine: it runs in Node, a Worker and the page. ' +
  'Put UI code in app/renderer, Electron code in app/main, blocks in blocks/.';

export default tseslint.config(
  { ignores: ['dist/**', 'node_modules/**', 'coverage/**', '**/*.d.ts'] },
  js.configs.recommended,
  ...tseslint.configs.recommended,
  {
    languageOptions: { ecmaVersion: 2022, sourceType: 'module' },
    rules: {
      '@typescript-eslint/no-unused-vars': ['error', { argsIgnorePattern: '^_', varsIgnorePattern: '^_' }],
      '@typescript-eslint/consistent-type-imports': 'error',
      'no-eval': 'error',
      'no-new-func': 'error',
      'no-implied-eval': 'error',
    },
  },
  {
    files: ['app/core/**/*.ts'],
    rules: {
      'no-restricted-imports': ['error', {
        patterns: [
          { group: ['**/renderer/**', '**/main/**', '**/cli/**', '**/blocks/**'], message: coreBoundary },
          { group: ['blockly', 'blockly/*', 'pixi.js', 'pixi.js/*', 'electron'], message: coreBoundary },
          { group: ['node:*', 'fs', 'path', 'os', 'child_process', 'worker_threads'], message: coreBoundary + ' File access belongs to the CLI and the Electron main process.' },
        ],
      }],
      'no-restricted-globals': ['error',
        { name: 'window', message: coreBoundary },
        { name: 'document', message: coreBoundary },
        { name: 'fetch', message: 'The engine does no I/O: the caller passes data in.' },
        { name: 'setTimeout', message: 'Time in the engine is the tick number, not the clock.' },
        { name: 'setInterval', message: 'Time in the engine is the tick number, not the clock.' },
        { name: 'performance', message: 'Time in the engine is the tick number; measure in the CLI or the app.' },
      ],
      'no-restricted-properties': ['error',
        { object: 'Date', property: 'now', message: 'Time in the engine is the tick number, not the clock.' },
        { object: 'Math', property: 'random', message: 'Use a seeded random source (app/core/session/random.ts) so runs replay exactly.' },
      ],
    },
  },
  {
    files: ['**/*.cjs', '**/*.mjs', '**/*.js'],
    languageOptions: { globals: { require: 'readonly', module: 'writable', process: 'readonly', __dirname: 'readonly', console: 'readonly' } },
    rules: { '@typescript-eslint/no-require-imports': 'off' },
  },
);
