import { validateController } from '../../../app/core/controller/validate';
import { controller, fn, forward, layer } from '../../support/controllers';

const messages = (c: Parameters<typeof validateController>[0]) => validateController(c).map((p) => `${p.path}: ${p.message}`);

describe('controller validation', () => {
  test('a sound controller has no problems', () => {
    expect(messages(controller([layer('Bottom', [forward()])]))).toEqual([]);
  });

  test('duplicate input names name both arcs', () => {
    const c = controller([
      layer('Bottom', [
        fn('a', 'number', [
          { name: 'x', from: { kind: 'world', input: 'tick' } },
          { name: 'x', from: { kind: 'world', input: 'heading' } },
        ], 'return x;'),
        forward(),
      ]),
    ]);
    expect(messages(c)).toEqual([
      expect.stringContaining('$.layers[0].functions[0].inputs[1].name: Function "a" (layer "Bottom") has two inputs named "x" (arcs 1 and 2, from the world\'s "tick" and the world\'s "heading")'),
    ]);
  });

  test('an arc from a missing function suggests a close name', () => {
    const c = controller([layer('Bottom', [fn('a', 'number', [{ name: 'v', from: { kind: 'function', function: 'stere' } }], 'return 1;'), fn('steer', 'string', [], "return 'left';"), forward()])]);
    expect(messages(c)).toEqual([expect.stringMatching(/inputs\[0\]\.from: .*reads the function "stere", but there is no function by that name\. Did you mean "steer"\?/)]);
  });

  test('unknown random sources and world inputs are explained', () => {
    const c = controller([
      layer('Bottom', [
        fn('a', 'number', [{ name: 'r', from: { kind: 'random', source: 'dice' } }, { name: 'w', from: { kind: 'world', input: 'sonar' as never } }], 'return 1;'),
        forward(),
      ]),
    ]);
    const m = messages(c);
    expect(m[0]).toContain('random source "dice"');
    expect(m[1]).toContain('world input "sonar", which does not exist. World inputs: robotPos');
  });

  test('a cycle within one tick names every function on it and suggests the previous tick', () => {
    const c = controller([
      layer('Top', [fn('a', 'number', [{ name: 'c', from: { kind: 'function', function: 'c' } }], 'return c;')]),
      layer('Middle', [fn('b', 'number', [{ name: 'a', from: { kind: 'function', function: 'a' } }], 'return a;')]),
      layer('Bottom', [fn('c', 'number', [{ name: 'b', from: { kind: 'function', function: 'b' } }], 'return b;'), forward()]),
    ]);
    const [m] = messages(c);
    expect(m).toMatch(/"a" \(layer "Top"\)/);
    expect(m).toMatch(/"b" \(layer "Middle"\)/);
    expect(m).toMatch(/"c" \(layer "Bottom"\)/);
    expect(m).toContain('from the previous tick');
  });

  test('the same cycle through a previous-tick arc is fine', () => {
    const c = controller([
      layer('Top', [fn('a', 'number', [{ name: 'b', from: { kind: 'previous', function: 'b', initial: 0 } }], 'return b + 1;')]),
      layer('Bottom', [fn('b', 'number', [{ name: 'a', from: { kind: 'function', function: 'a' } }], 'return a;'), forward()]),
    ]);
    expect(messages(c)).toEqual([]);
  });

  test('a missing body command is explained', () => {
    expect(messages(controller([layer('Bottom', [fn('go', 'move', [], 'return null;')])]))).toEqual([
      expect.stringContaining('$.bodyCommand: The body command is the function "changePos", but there is no function by that name'),
    ]);
  });

  test('names that clash with the language or the helpers are refused', () => {
    const c = controller([layer('Bottom', [fn('distance', 'number', [{ name: 'return', from: { kind: 'world', input: 'tick' } }], 'return 1;'), forward()])]);
    const m = messages(c);
    expect(m.some((x) => x.includes('"distance" is a word Layerbot keeps'))).toBe(true);
    expect(m.some((x) => x.includes('"return" is a word Layerbot keeps'))).toBe(true);
  });
});
