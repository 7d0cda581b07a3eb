/** Locked parts and block counting. */
import type { ControllerSpec } from '../../../app/core/controller/model';
import { countBlocks, lockChanges, normalizeBlocks } from '../../../app/core/packs';
import { exampleController } from '../../support/examples';

const basic = exampleController('basic');
const withLayer = (spec: ControllerSpec, name: string, change: (l: ControllerSpec['layers'][number]) => object): ControllerSpec => ({
  ...spec,
  layers: spec.layers.map((l) => (l.name === name ? ({ ...l, ...change(l) } as ControllerSpec['layers'][number]) : l)),
});

describe('lockChanges', () => {
  test('an unchanged controller keeps its locks, even with new block ids and positions', () => {
    const moved = JSON.parse(JSON.stringify(basic).replace(/"id":"(todo\.\d+)"/g, '"id":"$1x"').replace(/"x":20/g, '"x":99')) as ControllerSpec;
    expect(lockChanges(basic, moved, [{ layer: 'Top' }, { layer: 'Bottom', function: 'whiskerOn' }])).toEqual([]);
  });

  test('each kind of change, in words', () => {
    const timeout = withLayer(basic, 'Top', (l) => ({ variables: l.variables.map((v) => ({ ...v, value: 50 })) }));
    expect(lockChanges(basic, timeout, [{ layer: 'Top' }])).toEqual(['the locked layer "Top" was changed: its variable TIMEOUT is 50, not 200']);
    const fewer = withLayer(basic, 'Top', (l) => ({ functions: l.functions.slice(0, 2) }));
    expect(lockChanges(basic, fewer, [{ layer: 'Top' }])).toEqual(['the locked layer "Top" was changed: its function "timer" was removed or renamed']);
    const text = withLayer(basic, 'Bottom', (l) => ({ functions: l.functions.map((f) => (f.name === 'whiskerOn' ? { ...f, body: { kind: 'text', code: 'return false;' } } : f)) }));
    expect(lockChanges(basic, text, [{ layer: 'Bottom', function: 'whiskerOn' }])).toEqual(['the locked function "whiskerOn" (layer "Bottom") was changed: it was switched from blocks to text']);
    const gone = { ...basic, layers: basic.layers.filter((l) => l.name !== 'Top') };
    expect(lockChanges(basic, gone, [{ layer: 'Top' }])).toEqual(['the locked layer "Top" was removed or renamed']);
  });

  test('a changed block is a change; variables are compared by name', () => {
    const edited = JSON.parse(JSON.stringify(basic).replace('"TEXT":"left"', '"TEXT":"right"')) as ControllerSpec;
    expect(lockChanges(basic, edited, [{ layer: 'Middle', function: 'steer' }])).toEqual(['the locked function "steer" (layer "Middle") was changed: its blocks changed']);
    const renamed = { blocks: { blocks: [{ type: 'variables_get', fields: { VAR: { id: 'v2' } } }] }, variables: [{ name: 'goal', id: 'v2' }] };
    const original = { blocks: { blocks: [{ type: 'variables_get', id: 'q', fields: { VAR: { id: 'v1' } } }] }, variables: [{ name: 'goal', id: 'v1' }] };
    expect(normalizeBlocks(renamed)).toEqual(normalizeBlocks(original));
  });
});

describe('countBlocks', () => {
  test('every block object, without shadows or the variable list', () => {
    const body = {
      blocks: {
        languageVersion: 0,
        blocks: [
          {
            type: 'lb_function',
            inputs: {
              DO: { block: { type: 'variables_set', fields: { VAR: { id: 'v' } }, inputs: { VALUE: { shadow: { type: 'math_number' }, block: { type: 'math_number' } } }, next: { block: { type: 'text_print' } } } },
              RETURN: { shadow: { type: 'logic_boolean' } },
            },
          },
          { type: 'math_number' },
        ],
      },
      variables: [{ name: 'v', id: 'v', type: '' }],
    };
    expect(countBlocks(body)).toBe(5);
    expect(countBlocks({ type: 'math_number' })).toBe(1);
    expect(countBlocks(null)).toBe(0);
  });

  test('the example controllers', () => {
    const steer = basic.layers[1].functions.find((f) => f.name === 'steer')!;
    expect(steer.body.kind === 'blocks' && countBlocks(steer.body.blocks)).toBe(JSON.stringify(steer.body).match(/"type":/g)!.length);
  });
});
