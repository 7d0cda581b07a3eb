/**
 * The value-iteration controller's new functions as blocks (the original design, figure 2.5 and
 * section 2.2.6): the grid over the world, getHasWall (cells a wall passes through or comes within
 * WALL_MARGIN of), getHasGoal, currentState, valueIteration (re-run only when the to-do list
 * changes; the Q-values travel on a previous-tick arc), chooseAction (ties go to the action that
 * points closer to the goal), and a steer that heads for the centre of the cell the chosen action
 * leads to, or for the goal itself once that cell holds it.
 */
import type { BlockState } from '../../../blocks/build';
import { BodyBuilder } from '../../../blocks/build';
import type { BodyMaker } from './basic';
import { steerTowardsGoal } from './basic';

/** Q-values of one cell: the value after each action, minus its cost (north, east, south, west, stay). */
function neighbourValue(b: BodyBuilder, a: number): BlockState[] {
  // c, r: the neighbour's column and row. Off the grid or into a wall: the robot stays.
  const dc = [0, 1, 0, -1][a];
  const dr = [1, 0, -1, 0][a];
  const add = (name: 'column' | 'row', d: number) => (d === 0 ? b.get(name) : b.arith(d > 0 ? 'ADD' : 'MINUS', b.get(name), b.num(Math.abs(d))));
  const inside =
    dc !== 0
      ? dc > 0
        ? b.compare('LT', b.get('c'), b.get('cols'))
        : b.compare('GTE', b.get('c'), b.num(0))
      : dr > 0
        ? b.compare('LT', b.get('r'), b.get('rows'))
        : b.compare('GTE', b.get('r'), b.num(0));
  return [
    b.set('c', add('column', dc)),
    b.set('r', add('row', dr)),
    b.set('next', b.get('here')),
    b.if([[b.and(inside, b.not(b.tableGet(b.input('hasWall'), b.get('c'), b.get('r')))), [b.set('next', b.tableGet(b.get('values'), b.get('c'), b.get('r')))]]]),
    b.set(`q${a}`, b.arith('MINUS', b.get('next'), b.layerVar('ACTION_COST'))),
  ];
}

export const viBodies: Record<string, BodyMaker> = {
  todo() {
    const b = new BodyBuilder('todo');
    return b.body(
      [
        b.set('list', b.ternary(b.isEmpty(b.input('previousTodo')), b.input('plan'), b.input('previousTodo'))),
        b.if([[b.and(b.input('arrived'), b.compare('GT', b.length(b.get('list')), b.num(1))), [b.ret(b.restFrom(b.get('list'), b.num(2)))]]]),
      ],
      b.get('list'),
    );
  },
  grid() {
    const b = new BodyBuilder('grid');
    return b.body(
      // previousGrid is false on the first tick, then the grid made then.
      [b.if([[b.input('previousGrid'), [b.ret(b.input('previousGrid'))]]])],
      // WALL_MARGIN of room around the walls keeps a way open round the outside of the world.
      b.api('makeGridWithRoom', b.input('walls'), b.input('goals'), b.input('robotPos'), b.layerVar('CELL_SIZE'), b.layerVar('WALL_MARGIN')),
    );
  },
  getHasWall() {
    const b = new BodyBuilder('getHasWall');
    return b.body(
      [
        b.set('hasWall', b.api('newGrid', b.input('grid'), b.bool(false))),
        b.forEach('wall', b.input('walls'), [
          b.forEach('cell', b.api('cellsNearWall', b.input('grid'), b.get('wall'), b.layerVar('WALL_MARGIN')), [
            b.tableSet(b.get('hasWall'), b.cellPart('COL', b.get('cell')), b.cellPart('ROW', b.get('cell')), b.bool(true)),
          ]),
        ]),
      ],
      b.get('hasWall'),
    );
  },
  getHasGoal() {
    const b = new BodyBuilder('getHasGoal');
    return b.body(
      [
        b.set('hasGoal', b.api('newGrid', b.input('grid'), b.bool(false))),
        b.set('cell', b.api('cellOf', b.input('grid'), b.api('goalPosition', b.input('goals'), b.first(b.input('todo'))))),
        b.if([[b.api('inGrid', b.input('grid'), b.get('cell')), [b.tableSet(b.get('hasGoal'), b.cellPart('COL', b.get('cell')), b.cellPart('ROW', b.get('cell')), b.bool(true))]]]),
      ],
      b.get('hasGoal'),
    );
  },
  currentState() {
    const b = new BodyBuilder('currentState');
    return b.body([], b.api('cellOf', b.input('grid'), b.input('robotPos')));
  },
  valueIteration() {
    const b = new BodyBuilder('valueIteration');
    const qs = [0, 1, 2, 3].flatMap((a) => neighbourValue(b, a));
    return b.body(
      [
        b.if([[b.not(b.input('todoChanged')), [b.ret(b.input('previousQValues'))]]]),
        b.set('cols', b.gridSize('cols', b.input('grid'))),
        b.set('rows', b.gridSize('rows', b.input('grid'))),
        b.set('values', b.api('newGrid', b.input('grid'), b.num(0))),
        b.set('qValues', b.api('newGrid', b.input('grid'), b.num(0))),
        b.set('changed', b.bool(true)),
        b.set('backward', b.bool(true)),
        b.whileTrue(b.get('changed'), [
          b.set('changed', b.bool(false)),
          // Every other sweep visits the cells from the last to the first: values spread both ways.
          b.set('backward', b.not(b.get('backward'))),
          b.forEachCell(b.input('grid'), 'i', 'j', [
            b.set('column', b.ternary(b.get('backward'), b.arith('MINUS', b.arith('MINUS', b.get('cols'), b.num(1)), b.get('i')), b.get('i'))),
            b.set('row', b.ternary(b.get('backward'), b.arith('MINUS', b.arith('MINUS', b.get('rows'), b.num(1)), b.get('j')), b.get('j'))),
            b.set('here', b.tableGet(b.get('values'), b.get('column'), b.get('row'))),
            ...qs,
            b.set('q4', b.arith('MINUS', b.get('here'), b.layerVar('ACTION_COST'))),
            b.if(
              [
                [b.tableGet(b.input('hasGoal'), b.get('column'), b.get('row')), [b.set('best', b.layerVar('GOAL_REWARD')), b.set('q4', b.layerVar('GOAL_REWARD'))]],
                [b.tableGet(b.input('hasWall'), b.get('column'), b.get('row')), [b.set('best', b.num(0))]],
              ],
              [b.set('best', b.max(b.list(b.num(0), b.get('q0'), b.get('q1'), b.get('q2'), b.get('q3'))))],
            ),
            b.if([[b.compare('NEQ', b.get('best'), b.get('here')), [b.tableSet(b.get('values'), b.get('column'), b.get('row'), b.get('best')), b.set('changed', b.bool(true))]]]),
            b.tableSet(b.get('qValues'), b.get('column'), b.get('row'), b.list(b.get('q0'), b.get('q1'), b.get('q2'), b.get('q3'), b.get('q4'))),
          ]),
        ]),
      ],
      b.get('qValues'),
    );
  },
  chooseAction() {
    const b = new BodyBuilder('chooseAction');
    const qOf = (action: BlockState) => b.item(b.get('q'), b.arith('ADD', action, b.num(1)));
    return b.body(
      [
        b.if([[b.not(b.api('inGrid', b.input('grid'), b.input('currentState'))), [b.ret(b.action(4))]]]),
        b.set('q', b.tableGet(b.input('qValues'), b.cellPart('COL', b.input('currentState')), b.cellPart('ROW', b.input('currentState')))),
        b.set('goalDirection', b.api('directionTo', b.input('robotPos'), b.api('goalPosition', b.input('goals'), b.first(b.input('todo'))))),
        b.set('best', b.action(4)),
        b.set('bestTurn', b.num(360)),
        b.forRange('action', b.num(0), b.num(3), b.num(1), [
          // How far the action's direction (north 90, east 0, south -90, west -180 degrees) is
          // from the goal's: of two equally good actions, the one that points closer to the goal wins.
          b.set('turn', b.single('ABS', b.api('normalizeAngle', b.arith('MINUS', b.arith('MINUS', b.num(90), b.arith('MULTIPLY', b.num(90), b.get('action'))), b.get('goalDirection'))))),
          b.if([
            [
              b.or(
                b.compare('GT', qOf(b.get('action')), qOf(b.get('best'))),
                b.and(b.compare('EQ', qOf(b.get('action')), qOf(b.get('best'))), b.compare('LT', b.get('turn'), b.get('bestTurn'))),
              ),
              [b.set('best', b.get('action')), b.set('bestTurn', b.get('turn'))],
            ],
          ]),
        ]),
      ],
      b.get('best'),
    );
  },
  steer() {
    const b = new BodyBuilder('steer');
    return b.body(
      [
        b.if([[b.input('whisker'), [b.ret(b.str('left'))]]]),
        // Head for the centre of the next cell of the plan, or for the goal itself once it is in
        // the next cell (or in this one: the action is to stay).
        b.set('nextCell', b.api('neighbourCell', b.input('currentState'), b.input('action'))),
        b.set('goal', b.api('cellCenter', b.input('grid'), b.get('nextCell'))),
        b.if([
          [
            b.or(
              b.compare('EQ', b.input('action'), b.action(4)),
              b.and(b.api('inGrid', b.input('grid'), b.get('nextCell')), b.tableGet(b.input('hasGoal'), b.cellPart('COL', b.get('nextCell')), b.cellPart('ROW', b.get('nextCell')))),
            ),
            [b.set('goal', b.api('goalPosition', b.input('goals'), b.first(b.input('todo'))))],
          ],
        ]),
        ...steerTowardsGoal(b),
      ],
      b.str('straight'),
    );
  },
};
