/**
 * Runaway code in the fast engine becomes a failure naming the function and layer: loops and
 * recursion are stopped by the guards, slow built-ins and huge allocations by the worker's watchdog.
 */
import { errorOf } from './helpers';

const where = 'Error in function "changePos" (layer "Bottom"): ';

describe('the fast engine stops runaway code', () => {
  test('an endless loop runs out of steps, even inside try/catch/finally', async () => {
    const e = await errorOf('try { while (true) {} } catch (err) { } finally { for (;;) {} }');
    expect(e).toMatchObject({ tick: 1, function: 'changePos', layer: 'Bottom', kind: 'budget' });
    expect(e?.message).toBe(`${where}it ran for more than 5,000,000 steps without finishing. Check its loops: is there one that never ends?`);
  });

  test('writing to an input is a mutation error naming the input', async () => {
    const e = await errorOf('goals[0].x = 3;');
    expect(e?.kind).toBe('mutation');
    expect(e?.message).toBe(`${where}it tried to change its input "goals". Inputs cannot be changed: make a copy first (the "copy list" block) and change the copy.`);
    expect((await errorOf('plan.push("o103");'))?.message).toContain('its input "plan"');
  });

  test('a copy of an input can be changed', async () => {
    expect(await errorOf('var p = copyList(plan); p.push("x"); p[0] = "y";')).toBeNull();
  });

  test('endless recursion is a resources error', async () => {
    const e = await errorOf('function down(n) { try { return down(n + 1) + 1; } catch (err) { return 0; } } down(0);');
    expect(e?.kind).toBe('resources');
    expect(e?.message).toBe(`${where}its calls went too deep. Check its recursion: does every recursive call get closer to a case that stops?`);
  });

  test('a text doubled without end is a resources error', async () => {
    const e = await errorOf('var s = "x"; while (true) s = s + s;');
    expect(e?.kind).toBe('resources');
    expect(e?.message).toMatch(/needed more memory than a function may use/);
  });

  test('a huge list cannot leave the function', async () => {
    const e = await errorOf('var a = []; a[2e9] = 1; return a;');
    expect(e?.kind).toBe('resources');
  });

  test('a huge allocation kills only the worker, and the error names the function', async () => {
    const e = await errorOf('var a = []; for (var i = 0; i < 50; i++) a.push(new Array(1 << 22).fill(i + 0.5));', { memoryMb: 64 });
    expect(e).toMatchObject({ tick: 1, function: 'changePos', layer: 'Bottom', kind: 'resources' });
    expect(e?.message).toMatch(/^Error in function "changePos" \(layer "Bottom"\): it needed more memory than a function may use, and was stopped\.$/);
  });

  test('a catastrophic regular expression is stopped by the watchdog, naming the function', async () => {
    const e = await errorOf('/^(a+)+$/.test("aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa!");', { callLimitMs: 300 });
    expect(e).toMatchObject({ tick: 1, function: 'changePos', layer: 'Bottom', kind: 'resources' });
    expect(e?.message).toBe(
      `${where}it ran for more than 0.3 seconds in one tick and was stopped. The step budget cannot stop a slow built-in operation: look for a regular expression that backtracks a lot, or a huge text or list.`,
    );
  });
});
