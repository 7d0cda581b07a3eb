/**
 * The bodies of the basic controller's functions as blocks (the textbook robot, Poole & Mackworth
 * ch. 2). Each builder reproduces the text-mode function it replaces, step for step.
 */
import { BodyBuilder } from '../../../blocks/build';
import type { JsonValue } from '../../../app/core/values';

export type BodyMaker = () => JsonValue;

export const basicBodies: Record<string, BodyMaker> = {
  todo() {
    const b = new BodyBuilder('todo');
    return b.body(
      [
        b.set('list', b.ternary(b.isEmpty(b.input('previousTodo')), b.input('plan'), b.input('previousTodo'))),
        b.if([
          [
            b.and(b.or(b.input('arrived'), b.compare('GTE', b.input('previousTimer'), b.layerVar('TIMEOUT'))), b.compare('GT', b.length(b.get('list')), b.num(1))),
            [b.ret(b.restFrom(b.get('list'), b.num(2)))],
          ],
        ]),
      ],
      b.get('list'),
    );
  },
  todoChanged() {
    const b = new BodyBuilder('todoChanged');
    return b.body([], b.compare('NEQ', b.length(b.input('todo')), b.length(b.input('previousTodo'))));
  },
  timer() {
    const b = new BodyBuilder('timer');
    return b.body([b.if([[b.input('todoChanged'), [b.ret(b.num(1))]]])], b.arith('ADD', b.input('previousTimer'), b.num(1)));
  },
  arrived() {
    const b = new BodyBuilder('arrived');
    return b.body(
      [
        b.if([[b.isEmpty(b.input('previousTodo')), [b.ret(b.bool(false))]]]),
        b.set('goal', b.api('goalPosition', b.input('goals'), b.first(b.input('previousTodo')))),
        b.set('dx', b.arith('MINUS', b.pointPart('X', b.get('goal')), b.pointPart('X', b.input('robotPos')))),
        b.set('dy', b.arith('MINUS', b.pointPart('Y', b.get('goal')), b.pointPart('Y', b.input('robotPos')))),
      ],
      b.compare('LTE', b.arith('ADD', b.arith('MULTIPLY', b.get('dx'), b.get('dx')), b.arith('MULTIPLY', b.get('dy'), b.get('dy'))), b.arith('MULTIPLY', b.layerVar('CLOSE'), b.layerVar('CLOSE'))),
    );
  },
  steer() {
    const b = new BodyBuilder('steer');
    return b.body(
      [
        b.if([[b.input('whisker'), [b.ret(b.str('left'))]]]),
        b.set('goal', b.api('goalPosition', b.input('goals'), b.first(b.input('todo')))),
        ...steerTowardsGoal(b),
      ],
      b.str('straight'),
    );
  },
  whiskerOn() {
    const b = new BodyBuilder('whiskerOn');
    return b.body(
      [b.set('tip', b.api('pointAt', b.input('robotPos'), b.arith('ADD', b.input('heading'), b.layerVar('WHISKER_ANGLE')), b.layerVar('WHISKER_LENGTH')))],
      b.api('touchesAnyWall', b.list(b.input('robotPos'), b.get('tip')), b.input('walls')),
    );
  },
  lowLevelSteer() {
    const b = new BodyBuilder('lowLevelSteer');
    return b.body(
      [
        b.set('turn', b.num(0)),
        b.if(
          [
            [b.compare('EQ', b.input('steer'), b.str('left')), [b.set('turn', b.layerVar('TURN'))]],
            [b.compare('EQ', b.input('steer'), b.str('right')), [b.set('turn', b.single('NEG', b.layerVar('TURN')))]],
          ],
        ),
      ],
      b.modulo(b.arith('ADD', b.arith('ADD', b.input('heading'), b.get('turn')), b.num(360)), b.num(360)),
    );
  },
  changePos() {
    const b = new BodyBuilder('changePos');
    return b.body(
      [],
      b.move(
        b.input('newHeading'),
        b.arith('MULTIPLY', b.layerVar('SPEED'), b.trig('COS', b.input('newHeading'))),
        b.arith('MULTIPLY', b.layerVar('SPEED'), b.trig('SIN', b.input('newHeading'))),
      ),
    );
  },
};

/**
 * The statements that steer toward the point in the variable `goal`, as the textbook's robot
 * does: 'left' or 'right' when the goal is more than STRAIGHT degrees off the heading (they
 * return); the caller returns 'straight' after them.
 */
export function steerTowardsGoal(b: BodyBuilder) {
  const x = (p: 'X' | 'Y', of: 'goal' | 'robotPos') => b.pointPart(p, of === 'goal' ? b.get('goal') : b.input('robotPos'));
  return [
    b.set('dx', b.arith('MINUS', x('X', 'goal'), x('X', 'robotPos'))),
    b.set('dy', b.arith('MINUS', x('Y', 'goal'), x('Y', 'robotPos'))),
    b.set(
      'goalDir',
      b.trig('ACOS', b.arith('DIVIDE', b.get('dx'), b.single('ROOT', b.arith('ADD', b.arith('MULTIPLY', b.get('dx'), b.get('dx')), b.arith('MULTIPLY', b.get('dy'), b.get('dy')))))),
    ),
    b.if([[b.compare('GT', x('Y', 'robotPos'), x('Y', 'goal')), [b.set('goalDir', b.single('NEG', b.get('goalDir')))]]]),
    b.set('goalFromRobot', b.arith('MINUS', b.modulo(b.arith('ADD', b.arith('MINUS', b.get('goalDir'), b.input('heading')), b.num(540)), b.num(360)), b.num(180))),
    b.if([
      [b.compare('GT', b.get('goalFromRobot'), b.layerVar('STRAIGHT')), [b.ret(b.str('left'))]],
      [b.compare('LT', b.get('goalFromRobot'), b.single('NEG', b.layerVar('STRAIGHT'))), [b.ret(b.str('right'))]],
    ]),
  ];
}
