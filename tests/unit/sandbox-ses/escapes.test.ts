/**
 * Student code in the fast engine reaches nothing outside its compartment: no host globals, no
 * module loader, no code made from text, no constructor escapes, nothing left for the next call.
 */
import { errorOf, printedBy } from './helpers';

/** Runs each attempt and prints what it gave (or the error it threw). */
const attempts = (list: string[]): string =>
  list.map((code) => `try { print(String(${code})); } catch (err) { print('threw ' + err.name + ': ' + err.message); }`).join('\n');

describe('the fast engine keeps student code inside its sandbox', () => {
  test('host globals are not there', async () => {
    expect(await printedBy(attempts(['typeof process', 'typeof require', 'typeof globalThis', 'typeof module', 'typeof Compartment', 'typeof lockdown', 'typeof harden', 'typeof Proxy', 'typeof Promise']))).toEqual(
      Array(9).fill('undefined'),
    );
    expect(await printedBy(attempts(['process.exit', 'globalThis.process']))).toEqual([
      'threw ReferenceError: process is not defined',
      'threw ReferenceError: globalThis is not defined',
    ]);
  });

  test('code cannot be made from text', async () => {
    const refused = 'Making code from text (Function, eval) is not available here: write the code in the function itself.';
    expect(
      await printedBy(
        attempts([
          "Function('return this')()",
          "eval('1 + 1')",
          "(function () {}).constructor('return process')()",
          "distance.constructor('return process')()",
          "[].map.constructor('return this')()",
          "Object.getPrototypeOf(function () {}).constructor('return this')()",
        ]),
      ),
    ).toEqual([
      `threw Error: ${refused}`,
      `threw Error: ${refused}`,
      'threw TypeError: Function.prototype.constructor is not a valid constructor.',
      'threw TypeError: Function.prototype.constructor is not a valid constructor.',
      'threw TypeError: Function.prototype.constructor is not a valid constructor.',
      'threw TypeError: Function.prototype.constructor is not a valid constructor.',
    ]);
  });

  test('clocks and randomness are refused with a clear message', async () => {
    const e = await errorOf('var r = Math.random();');
    expect(e?.message).toBe(
      'Error in function "changePos" (layer "Bottom"): Math.random is not available here: use a random input instead (a random source), so that every run can be replayed exactly.',
    );
    expect((await errorOf('var t = Date.now();'))?.message).toMatch(/Date is not available here: use the "tick" input/);
    expect((await errorOf('var t = new Date();'))?.message).toMatch(/Date is not available here/);
  });

  test('built-ins cannot be changed', async () => {
    expect(await printedBy(attempts(['Math.floor = null', 'Array.prototype.push = null', 'Object.prototype.x = 1', 'print.x = 1']))).toEqual([
      "threw TypeError: Cannot assign to read only property 'floor' of object '[object Math]'",
      "threw TypeError: Cannot assign to read only property 'push' of object '[object Array]'",
      'threw TypeError: Cannot add property x, object is not extensible',
      'threw TypeError: Cannot add property x, object is not extensible',
    ]);
  });

  test('a write to a built-in that is not caught is an exception, not a mutation of an input', async () => {
    const e = await errorOf('Array.prototype.push = null;');
    expect(e?.kind).toBe('exception');
    expect(e?.message).toBe('Error in function "changePos" (layer "Bottom"): TypeError: Cannot change "push": built-in values and functions are read-only.');
  });

  test("the engine's own bindings cannot be named", async () => {
    await expect(errorOf('$lb$s = 1e9;')).rejects.toThrow(/the name "\$lb\$s" is reserved/);
  });

  test('text that looks like eval or an HTML comment still runs', async () => {
    expect(await printedBy('/* eval( import( */ print("eval(1) <!-- import(x) -->"); var n = 3; if (n-->2) print(String(n));')).toEqual([
      'eval(1) <!-- import(x) -->',
      '2',
    ]);
  });
});
