/**
 * Builds the example controllers' files from the basic controller's structure (its layers,
 * function names, arcs, descriptions and variables) and the block bodies of basic.ts and
 * value-iteration.ts. Run `UPDATE_EXAMPLES=1 npx jest tests/golden/examples.test.ts` to rewrite
 * examples/controllers/*.controller.json; the files are the source of truth afterwards.
 */
import type { ControllerSpec, FunctionSpec, InputSpec, LayerSpec } from '../../../app/core/controller/model';
import type { JsonValue, ValueType } from '../../../app/core/values';
import { BodyBuilder } from '../../../blocks/build';
import type { BodyMaker } from './basic';
import { basicBodies } from './basic';
import { viBodies } from './value-iteration';

const world = (name: string, input: string): InputSpec => ({ name, from: { kind: 'world', input } as InputSpec['from'] });
const fnArc = (name: string, fn: string): InputSpec => ({ name, from: { kind: 'function', function: fn } });
const prev = (name: string, fn: string, initial: JsonValue): InputSpec => ({ name, from: { kind: 'previous', function: fn, initial } });

function withBodies(layer: LayerSpec, bodies: Record<string, BodyMaker>): LayerSpec {
  return {
    ...layer,
    functions: layer.functions.map((fn) => {
      const make = bodies[fn.name];
      if (!make) throw new Error(`No block body for function "${fn.name}"`);
      return { ...fn, body: { kind: 'blocks', blocks: make() } };
    }),
  };
}

function fn(name: string, description: string, output: ValueType, inputs: InputSpec[], make: BodyMaker): FunctionSpec {
  return { name, description, output, inputs, body: { kind: 'blocks', blocks: make() } };
}

/** The basic controller with every body as blocks. */
export function basicController(basic: ControllerSpec): ControllerSpec {
  return { ...basic, layers: basic.layers.map((l) => withBodies(l, basicBodies)) };
}

/** Basic with a seeded random input in the top layer: a random patience for each goal. */
export function basicRandomController(basic: ControllerSpec): ControllerSpec {
  const b = basicController(basic);
  const [top, ...rest] = b.layers;
  const todo = top.functions.find((f) => f.name === 'todo')!;
  const randomTodo: FunctionSpec = {
    ...todo,
    description: 'The goals still to visit. Starts with the whole plan; drops the first goal when the robot arrived there or tried for longer than its patience. The last goal stays.',
    inputs: [...todo.inputs, prev('previousPatience', 'patience', 200)],
    body: {
      kind: 'blocks',
      blocks: (() => {
        const t = new BodyBuilder('todo');
        return t.body(
          [
            t.set('list', t.ternary(t.isEmpty(t.input('previousTodo')), t.input('plan'), t.input('previousTodo'))),
            t.if([
              [
                t.and(t.or(t.input('arrived'), t.compare('GTE', t.input('previousTimer'), t.input('previousPatience'))), t.compare('GT', t.length(t.get('list')), t.num(1))),
                [t.ret(t.restFrom(t.get('list'), t.num(2)))],
              ],
            ]),
          ],
          t.get('list'),
        );
      })(),
    },
  };
  const patience = fn(
    'patience',
    'How many ticks the robot tries to reach the current goal: drawn from the random input "draw" whenever the to-do list changes.',
    'number',
    [prev('previousPatience', 'patience', 200), fnArc('todoChanged', 'todoChanged'), { name: 'draw', from: { kind: 'random', source: 'draw' } }],
    () => {
      const p = new BodyBuilder('patience');
      return p.body([p.if([[p.input('todoChanged'), [p.print(p.join(p.str('patience for the next goal: '), p.input('draw'))), p.ret(p.input('draw'))]]])], p.input('previousPatience'));
    },
  );
  const newTop: LayerSpec = {
    ...top,
    description: 'Which goal next, with a random patience for each goal (a seeded random input: the same seed gives the same run).',
    variables: top.variables.filter((v) => v.name !== 'TIMEOUT'),
    randomSources: [{ name: 'draw', type: 'int', seed: 7, min: 100, max: 300 }],
    functions: top.functions.map((f) => (f.name === 'todo' ? randomTodo : f)).concat(patience),
  };
  return {
    ...b,
    name: 'Basic controller with a random input',
    description: 'The basic controller, whose top layer gives up on a goal after a random number of ticks drawn from a seeded random input (the original design, figure 3.21).',
    layers: [newTop, ...rest],
  };
}

/** Basic with its top layer swapped for one that visits the nearest unreached goal first. */
export function nearestGoalController(basic: ControllerSpec): ControllerSpec {
  const b = basicController(basic);
  const [top, ...rest] = b.layers;
  const todo = top.functions.find((f) => f.name === 'todo')!;
  const nearestTodo: FunctionSpec = {
    ...todo,
    description: 'The goals still to visit, the nearest one first. Starts with the goals of the plan; when the robot arrives (or gives up after TIMEOUT ticks), drops that goal and picks the nearest of the rest. The last goal stays.',
    inputs: [...todo.inputs, world('robotPos', 'robotPos'), world('goals', 'goals')],
    body: {
      kind: 'blocks',
      blocks: (() => {
        const t = new BodyBuilder('todo');
        const distanceTo = (name: ReturnType<BodyBuilder['get']>) => t.api('distance', t.input('robotPos'), t.api('goalPosition', t.input('goals'), name));
        return t.body(
          [
            t.set('list', t.ternary(t.isEmpty(t.input('previousTodo')), t.input('plan'), t.input('previousTodo'))),
            t.if(
              [
                [
                  t.or(t.input('arrived'), t.compare('GTE', t.input('previousTimer'), t.layerVar('TIMEOUT'))),
                  [
                    t.set('rest', t.api('listWithout', t.get('list'), t.first(t.get('list')))),
                    t.if([[t.not(t.isEmpty(t.get('rest'))), [t.set('list', t.get('rest'))]]]),
                  ],
                ],
                [t.not(t.isEmpty(t.input('previousTodo'))), [t.ret(t.get('list'))]],
              ],
            ),
            t.set('nearest', t.first(t.get('list'))),
            t.set('best', distanceTo(t.get('nearest'))),
            t.forEach('name', t.get('list'), [
              t.set('d', distanceTo(t.get('name'))),
              t.if([[t.compare('LT', t.get('d'), t.get('best')), [t.set('best', t.get('d')), t.set('nearest', t.get('name'))]]]),
            ]),
          ],
          t.api('moveToFront', t.get('list'), t.get('nearest')),
        );
      })(),
    },
  };
  return {
    ...b,
    name: 'Nearest goal first',
    description: 'The basic controller with its top layer swapped: instead of following the plan in order, the robot heads for the nearest goal it has not reached yet. The middle and bottom layers are unchanged.',
    layers: [{ ...top, name: 'Top (nearest goal)', description: 'Which goal next: the nearest goal not yet visited.', functions: top.functions.map((f) => (f.name === 'todo' ? nearestTodo : f)) }, ...rest],
  };
}

/** The value-iteration controller (original design, figure 2.5): four layers. */
export function valueIterationController(basic: ControllerSpec): ControllerSpec {
  const b = basicController(basic);
  const middle = b.layers.find((l) => l.functions.some((f) => f.name === 'steer'))!;
  const bottom = b.layers.find((l) => l.functions.some((f) => f.name === 'changePos'))!;
  const arrived = middle.functions.find((f) => f.name === 'arrived')!;
  const top: LayerSpec = {
    name: 'Top',
    description: 'Which goals are left: the to-do list, and whether it just changed (which triggers a new plan).',
    variables: [],
    randomSources: [],
    functions: [
      fn('todo', 'The goals still to visit, in plan order. Drops the first goal when the robot arrived there; the last goal stays.', 'list', [prev('previousTodo', 'todo', []), world('plan', 'plan'), fnArc('arrived', 'arrived')], viBodies.todo),
      fn('todoChanged', 'True on the tick the to-do list changes: then valueIteration plans again.', 'boolean', [prev('previousTodo', 'todo', []), fnArc('todo', 'todo')], basicBodies.todoChanged),
    ],
  };
  const vi: LayerSpec = {
    name: 'Value iteration',
    description:
      'Plans on a grid laid over the world: which cells are blocked and which holds the goal, the value of every action in every cell (value iteration), and the best action in the robot\'s cell. CELL_SIZE: the side of a cell, in world units. WALL_MARGIN: a cell is blocked when a wall passes through it or its centre is closer than this to a wall, so the plan keeps the robot that far from walls (3: the whisker reaches 3 units to the right of the robot, so on the plan it stays clear of walls). ACTION_COST: what each move costs. GOAL_REWARD: the value of the goal\'s cell.',
    variables: [
      { name: 'CELL_SIZE', value: 4 },
      { name: 'WALL_MARGIN', value: 3 },
      { name: 'ACTION_COST', value: 1 },
      { name: 'GOAL_REWARD', value: 1000 },
    ],
    randomSources: [],
    functions: [
      fn('grid', 'The grid of CELL_SIZE cells over the walls, goals and the robot, with WALL_MARGIN of room around them, made on the first tick and kept.', 'record', [prev('previousGrid', 'grid', false), world('walls', 'walls'), world('goals', 'goals'), world('robotPos', 'robotPos')], viBodies.grid),
      fn('getHasWall', 'A table of the grid: true in every blocked cell, that is every cell a wall passes through or whose centre is closer than WALL_MARGIN to a wall.', 'list', [world('walls', 'walls'), fnArc('grid', 'grid')], viBodies.getHasWall),
      fn('getHasGoal', 'A table of the grid: true in the cell of the next goal.', 'list', [fnArc('todo', 'todo'), world('goals', 'goals'), fnArc('grid', 'grid')], viBodies.getHasGoal),
      fn('currentState', 'The cell [column, row] the robot is in.', 'point', [world('robotPos', 'robotPos'), fnArc('grid', 'grid')], viBodies.currentState),
      fn(
        'valueIteration',
        'The Q-values: for every cell, the value of each action (north, east, south, west, stay). Computed again only when the to-do list changes; otherwise the previous tick\'s Q-values are passed on.',
        'list',
        [prev('previousQValues', 'valueIteration', []), fnArc('hasWall', 'getHasWall'), fnArc('hasGoal', 'getHasGoal'), fnArc('todoChanged', 'todoChanged'), fnArc('grid', 'grid')],
        viBodies.valueIteration,
      ),
      fn('chooseAction', 'The best action in the robot\'s cell: 0 north, 1 east, 2 south, 3 west, 4 stay. Of two equally good actions, the one that points closer to the goal wins (so the robot cuts across open ground and turns early at corners).', 'number', [fnArc('qValues', 'valueIteration'), fnArc('currentState', 'currentState'), fnArc('grid', 'grid'), world('robotPos', 'robotPos'), fnArc('todo', 'todo'), world('goals', 'goals')], viBodies.chooseAction),
    ],
  };
  const steer = fn(
    'steer',
    'Left when the whisker touches a wall; otherwise turn toward the centre of the cell the chosen action leads to, or toward the goal itself when that cell holds the goal or the action is to stay: left or right when it is more than STRAIGHT degrees off, else straight.',
    'string',
    [
      world('robotPos', 'robotPos'),
      world('heading', 'heading'),
      fnArc('whisker', 'whiskerOn'),
      fnArc('currentState', 'currentState'),
      fnArc('action', 'chooseAction'),
      fnArc('hasGoal', 'getHasGoal'),
      fnArc('todo', 'todo'),
      world('goals', 'goals'),
      fnArc('grid', 'grid'),
    ],
    viBodies.steer,
  );
  return {
    name: 'Value iteration',
    description:
      'Four layers after the original design (figure 2.5): the top layer keeps the to-do list, a value-iteration layer plans on a grid, the middle layer steers toward the next cell of the plan, and the bottom layer is the basic controller\'s. It finds its way out of the traps that defeat the basic controller and through the maze, keeping WALL_MARGIN away from walls.',
    bodyCommand: b.bodyCommand,
    // One valueIteration run on the maze's grid takes about 3.9 million steps in JS-Interpreter:
    // room for bigger worlds or smaller cells before the run stops (the default is 5 million).
    stepBudget: 20_000_000,
    layers: [top, vi, { ...middle, functions: [steer, arrived] }, bottom],
  };
}
