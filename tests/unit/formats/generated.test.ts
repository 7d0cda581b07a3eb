import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

const FORMATS = join(__dirname, '../../../app/core/formats');

describe('generated validators', () => {
  it('are up to date with the schemas (run `node app/core/formats/build-validators.cjs` if not)', () => {
    // --check regenerates in memory and exits with 1, naming the stale files, when they differ.
    let output = '';
    try {
      output = execFileSync(process.execPath, [join(FORMATS, 'build-validators.cjs'), '--check'], { encoding: 'utf8', stdio: 'pipe' });
    } catch (e) {
      const err = e as { stderr?: string; stdout?: string };
      throw new Error(`The generated validators are out of date:\n${err.stderr ?? ''}${err.stdout ?? ''}`);
    }
    expect(output).toContain('up to date');
  });

  it.each(['world.validate.js', 'controller.validate.js'])('%s stands alone and generates no code at run time', (file) => {
    const code = readFileSync(join(FORMATS, 'generated', file), 'utf8');
    expect(code).not.toMatch(/\brequire\(|^\s*import\s/m);
    expect(code).not.toMatch(/new Function|\beval\(/);
  });
});
