/** Each criterion, passing and failing, with the exact words of its verdict. */
import type { Reason } from '../../../app/core/packs';
import { gradeChallenge, judge, verdictSummary } from '../../../app/core/packs';
import { parseController } from '../../../app/core/formats';
import { challenge, controller, options, pack, world } from './fixtures';
import type { Json } from './fixtures';

function verdict(criteria: Json[], submitted: Json = controller(), extra: Json = {}) {
  const c = pack([challenge({ criteria, ...extra })]).challenges[0];
  const parsed = parseController(JSON.stringify(submitted), 'x.controller.json');
  if (!parsed.ok) throw new Error(JSON.stringify(parsed.problems));
  return gradeChallenge(c, parsed.value, options);
}

const line = (r: Reason) => `${r.passed ? 'PASS' : 'FAIL'} ${r.criterion}${r.world ? ` [${r.world}]` : ''}: ${r.detail}`;
const lines = (criteria: Json[], submitted?: Json, extra?: Json) => verdict(criteria, submitted, extra).reasons.map(line);
const ABC = { world: world({ plan: ['a', 'b', 'c'] }) };

describe('reachGoals', () => {
  test('the plan, in order: the tick of each goal', () => {
    expect(lines([{ kind: 'reachGoals' }])).toEqual(['PASS locked parts unchanged: layer "Bottom" unchanged', 'PASS reach the plan (a, b) in order: reached a at tick 8, b at tick 18']);
  });

  test('goals not reached say why the run ended', () => {
    expect(lines([{ kind: 'reachGoals', goals: ['a', 'c'], order: 'plan' }], controller(), ABC)[1]).toBe(
      'FAIL reach a, c in order: reached a at tick 8; c not reached (the robot crashed at tick 30)',
    );
    expect(lines([{ kind: 'reachGoals' }], controller({ speed: 'return 0.05;' }))[1]).toBe('FAIL reach the plan (a, b) in order: a and b not reached (not within 100 ticks)');
  });

  test('in any order, or in the order listed', () => {
    expect(lines([{ kind: 'reachGoals', goals: ['b', 'a'], order: 'any' }])[1]).toBe('PASS reach b, a in any order: reached b at tick 18, a at tick 8');
    expect(lines([{ kind: 'reachGoals', goals: ['b', 'a'], order: 'plan' }])[1]).toBe('FAIL reach b, a in order: reached b at tick 18; a not reached (the run ended at tick 18)');
  });
});

describe('withinTicks', () => {
  test('the last goal asked for, against the limit', () => {
    expect(lines([{ kind: 'reachGoals' }, { kind: 'withinTicks', ticks: 20 }])[2]).toBe('PASS within 20 ticks: the last goal, b, was reached at tick 18 (limit 20)');
    expect(lines([{ kind: 'withinTicks', ticks: 10 }])[1]).toBe('FAIL within 10 ticks: the last goal, b, was reached at tick 18, after tick 10');
    expect(lines([{ kind: 'reachGoals', goals: ['c'], order: 'any' }, { kind: 'withinTicks', ticks: 50 }], controller(), ABC)[2]).toBe(
      'FAIL within 50 ticks: c not reached (the robot crashed at tick 30)',
    );
  });
});

describe('noCrash and noError', () => {
  test('a crash names its tick and the wall', () => {
    expect(lines([{ kind: 'noCrash' }], controller(), ABC)[1]).toBe('FAIL no crash: crashed at tick 30: the wall at (30,-5)-(30,5)');
    expect(lines([{ kind: 'noCrash' }])[1]).toBe('PASS no crash: no crash in 18 ticks');
  });

  test('an error names its tick, function and layer', () => {
    const failing = controller({ move: "if (tick >= 5) throw new Error('boom'); return {heading: 0, dx: speed, dy: 0};" });
    expect(lines([{ kind: 'noError' }], failing, { locked: [] })[0]).toMatch(/^FAIL no error: at tick 5: Error in function "changePos" \(layer "Bottom"\): .*boom/);
    expect(lines([{ kind: 'noError' }])[1]).toBe('PASS no error: no error in 18 ticks');
  });

  test('a runaway loop is stopped by the step budget and judged', () => {
    const looping = { ...controller({ speed: 'while (true) {} return 1;' }), stepBudget: 10000 };
    expect(lines([{ kind: 'noError' }], looping)[1]).toMatch(/^FAIL no error: at tick 1: Error in function "speed" \(layer "Top"\): it ran for more than 10,000 steps/);
  });
});

describe('hasFunction and maxBlocks', () => {
  const escape = { name: 'Escape', functions: [{ name: 'avoid', output: 'boolean', inputs: [], body: { kind: 'text', code: 'return false;' } }] };

  test('a function in a layer', () => {
    expect(lines([{ kind: 'hasFunction', layer: 'Escape', function: 'avoid' }], controller({ extraLayer: escape }))[1]).toBe('PASS function "avoid" in layer "Escape": layer "Escape" has the function "avoid"');
    expect(lines([{ kind: 'hasFunction', layer: 'Escape', function: 'avoid' }])[1]).toBe(
      'FAIL function "avoid" in layer "Escape": there is no layer "Escape" (the layers are "Top" and "Bottom")',
    );
    expect(lines([{ kind: 'hasFunction', layer: 'Bottom', function: 'speed' }])[1]).toBe('FAIL function "speed" in layer "Bottom": layer "Bottom" has no function "speed" (it is in layer "Top")');
  });

  test('text functions cannot be counted', () => {
    expect(lines([{ kind: 'maxBlocks', blocks: 5 }])[1]).toBe('FAIL at most 5 blocks: cannot count the blocks of "speed" (layer "Top"): written as text, not blocks');
  });

  test('blocks in the editable functions, or in all', () => {
    const blocks = (n: number) => ({
      kind: 'blocks',
      blocks: { blocks: { languageVersion: 0, blocks: [{ type: 'lb_function', inputs: { RETURN: { block: n > 1 ? { type: 'math_number', fields: { NUM: n } } : undefined } } }] } },
    });
    const spec = controller();
    ((spec.layers as Json[])[0].functions as Json[])[0].body = blocks(2);
    const c = pack([challenge({ starter: spec, criteria: [{ kind: 'maxBlocks', blocks: 1 }, { kind: 'maxBlocks', blocks: 1, scope: 'all' }] })]).challenges[0];
    const v = judge(c, c.starter, []);
    expect(v.reasons.map(line)).toEqual([
      'PASS locked parts unchanged: layer "Bottom" unchanged',
      'FAIL at most 1 blocks: 2 blocks in the editable functions (at most 1): speed 2',
      'FAIL at most 1 blocks: cannot count the blocks of "changePos" (layer "Bottom"): written as text, not blocks',
    ]);
  });
});

describe('variants', () => {
  test('every run criterion on every world; the failing world is named', () => {
    const blocked = world({ name: 'Blocked', walls: [[[15, -5], [15, 5]]] });
    const v = verdict([{ kind: 'reachGoals' }, { kind: 'noCrash' }, { kind: 'variants', worlds: [blocked] }]);
    expect(v.passed).toBe(false);
    expect(v.reasons.map(line)).toEqual([
      'PASS locked parts unchanged: layer "Bottom" unchanged',
      'PASS reach the plan (a, b) in order [Corridor]: reached a at tick 8, b at tick 18',
      'PASS no crash [Corridor]: no crash in 18 ticks',
      'FAIL reach the plan (a, b) in order [variant 1 ("Blocked")]: reached a at tick 8; b not reached (the robot crashed at tick 15)',
      'FAIL no crash [variant 1 ("Blocked")]: crashed at tick 15: the wall at (15,-5)-(15,5)',
      'FAIL works on the challenge world and 1 variant: failed on variant 1 ("Blocked")',
    ]);
    expect(verdictSummary(v)).toBe(
      'on variant 1 ("Blocked"): reached a at tick 8; b not reached (the robot crashed at tick 15); on variant 1 ("Blocked"): crashed at tick 15: the wall at (15,-5)-(15,5); failed on variant 1 ("Blocked")',
    );
  });
});

describe('controllers that cannot run', () => {
  test('a graph problem is a verdict, not an exception', () => {
    const broken = controller();
    ((broken.layers as Json[])[1].functions as Json[])[0].inputs = [{ name: 'speed', from: { kind: 'function', function: 'nope' } }];
    expect(lines([{ kind: 'noCrash' }], broken)).toEqual([
      'FAIL locked parts unchanged: the locked layer "Bottom" was changed: function "changePos": its inputs (arcs) changed',
      'FAIL the controller runs: $.layers[1].functions[0].inputs[0].from: Function "changePos" (layer "Bottom"), input "speed" reads the function "nope", but there is no function by that name.',
    ]);
  });

  test('a syntax error is a verdict', () => {
    expect(lines([{ kind: 'noCrash' }], controller({ speed: 'return (;' }))[1]).toMatch(/^FAIL the controller runs: Error in function "speed" \(layer "Top"\)/);
  });
});

describe('verdictSummary', () => {
  test('says a part of a detail that two criteria share once, and keeps variant details whole', () => {
    const missed = 'storage and o103 not reached (not within 600 ticks)';
    const reasons: Reason[] = [
      { criterion: 'reach o109, storage, o103 in plan order', passed: false, detail: `reached o109 at tick 127; ${missed}` },
      { criterion: 'within 600 ticks', passed: false, detail: missed },
      { criterion: 'no crash', passed: true, detail: 'no crash in 600 ticks' },
      { criterion: 'no crash', world: 'variant 1', passed: false, detail: 'crashed at tick 9; the run stopped' },
    ];
    expect(verdictSummary({ passed: false, reasons })).toBe(`reached o109 at tick 127; ${missed}; on variant 1: crashed at tick 9; the run stopped`);
  });
});
