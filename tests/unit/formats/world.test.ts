import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { detectFormat, formatProblems, parseWorld, serializeWorld } from '../../../app/core/formats';
import type { FileProblem } from '../../../app/core/formats';
import type { WorldSpec } from '../../../app/core/world/world';

const EXAMPLES = join(__dirname, '../../../examples/worlds');

function problemsOf(text: string): readonly FileProblem[] {
  const r = parseWorld(text, 'w.world.json');
  if (r.ok) throw new Error('expected problems');
  return r.problems;
}

/** A valid world file as an object, to spoil one field at a time. */
function base(): Record<string, unknown> {
  return {
    format: 'layerbot-world',
    version: 1,
    name: 'Tiny',
    walls: [[[5, -5], [5, 5]]],
    goals: [
      { name: 'a', x: 10, y: 0 },
      { name: 'b', x: 0, y: 10 },
    ],
    plan: ['a', 'b', 'a'],
    robot: { x: 0, y: 0, heading: 0 },
  };
}

const text = (o: unknown) => JSON.stringify(o, null, 2);
const pathsAndMessages = (ps: readonly FileProblem[]) => ps.map((p) => `${p.path}: ${p.message}`);

describe('example worlds', () => {
  const files = readdirSync(EXAMPLES).filter((f) => f.endsWith('.world.json'));

  it('include the textbook worlds and our own', () => {
    expect(files.sort()).toEqual(
      ['corridor', 'field', 'maze', 'office', 'trap-new', 'trap'].map((n) => `${n}.world.json`).sort(),
    );
  });

  it.each(files)('%s parses, has a description and bounds, and round-trips', (file) => {
    const source = readFileSync(join(EXAMPLES, file), 'utf8');
    const r = parseWorld(source, file);
    if (!r.ok) throw new Error(formatProblems(r.problems));
    expect(r.value.description).toMatch(/\w/);
    expect(r.value.bounds).toBeDefined();
    expect(detectFormat(source)).toBe('world');
    const again = parseWorld(serializeWorld(r.value), file);
    expect(again.ok && again.value).toEqual(r.value);
    // The examples are written by serializeWorld, so they stay in its tidy layout.
    expect(serializeWorld(r.value)).toBe(source);
  });

  it('office is the textbook office', () => {
    const r = parseWorld(readFileSync(join(EXAMPLES, 'office.world.json'), 'utf8'), 'office');
    if (!r.ok) throw new Error('office does not parse');
    expect(r.value.walls).toEqual([
      [[20, 0], [30, 20]],
      [[70, -5], [70, 25]],
    ]);
    expect(r.value.goals).toEqual([
      { name: 'mail', x: -5, y: 10 },
      { name: 'o103', x: 50, y: 10 },
      { name: 'o109', x: 100, y: 10 },
      { name: 'storage', x: 101, y: 51 },
    ]);
    expect(r.value.plan).toEqual(['o109', 'storage', 'o109', 'o103']);
    expect(r.value.robot).toEqual({ x: 0, y: 0, heading: 90 });
  });
});

describe('parseWorld', () => {
  it('gives a deeply frozen WorldSpec with only the model fields', () => {
    const r = parseWorld(text({ $schema: '../world.schema.json', ...base(), goalRadius: 3, body: { whiskerLength: 4 } }), 'w');
    if (!r.ok) throw new Error(formatProblems(r.problems));
    const w: WorldSpec = r.value;
    expect(w).toEqual({ ...base(), format: undefined, version: undefined, goalRadius: 3, body: { whiskerLength: 4 } });
    expect('format' in w || '$schema' in w || 'bounds' in w).toBe(false);
    expect(Object.isFrozen(w) && Object.isFrozen(w.walls[0][1]) && Object.isFrozen(w.goals[1]) && Object.isFrozen(w.body)).toBe(true);
  });

  it('points at the line and column of a problem', () => {
    const ps = problemsOf(text({ ...base(), robot: { x: 0, y: 'zero', heading: 0 } }));
    expect(ps).toEqual([{ file: 'w.world.json', path: '$.robot.y', message: 'expected a number, found "zero"', line: 36, column: 10 }]);
  });

  it.each<[string, (o: Record<string, unknown>) => void, string[]]>([
    ['a wrong type', (o) => ((o.goals as object[])[0] = { name: 'a', x: 'ten', y: 0 }), ['$.goals[0].x: expected a number, found "ten"']],
    ['a list instead of a number', (o) => (o.robot = { x: [1], y: 0, heading: 0 }), ['$.robot.x: expected a number, found a list of 1 item']],
    [
      'a missing field',
      (o) => (o.robot = { x: 0, y: 0 }),
      ['$.robot: missing field "heading": the direction the robot faces at the start, in degrees counter-clockwise from east: 0 is east (+x), 90 is north (+y)'],
    ],
    ['a missing top-level field', (o) => delete o.plan, ['$: missing field "plan": the names of the goals to visit, in order']],
    ['an unknown field', (o) => ((o.goals as object[])[1] = { name: 'b', x: 0, y: 10, colour: 'red' }), ['$.goals[1].colour: unknown field "colour"; allowed: name, x, y']],
    ['a misspelt field', (o) => (o.robot = { x: 0, y: 0, heding: 0 }), [
      '$.robot: missing field "heading": the direction the robot faces at the start, in degrees counter-clockwise from east: 0 is east (+x), 90 is north (+y)',
      '$.robot.heding: unknown field "heding" (did you mean "heading"?); allowed: x, y, heading',
    ]],
    ['a point with three numbers', (o) => (o.walls = [[[0, 0], [1, 2, 3]]]), ['$.walls[0][1]: expected exactly 2 items in a point, like [0, 0], found 3']],
    ['a wall that is a number', (o) => (o.walls = [7]), ['$.walls[0]: expected a list [...] (a wall, like [[0, 0], [10, 0]]), found 7']],
    ['an empty name', (o) => (o.name = '  '), ['$.name: the world name must not be empty']],
    ['a zero goal radius', (o) => (o.goalRadius = 0), ['$.goalRadius: expected a number greater than 0, found 0']],
    ['a negative whisker', (o) => (o.body = { whiskerLength: -1 }), ['$.body.whiskerLength: expected a number at least 0, found -1']],
    ['incomplete bounds', (o) => (o.bounds = { minX: 0, minY: 0, maxX: 1 }), ['$.bounds: missing field "maxY": the top edge of the rectangle; larger than minY']],
  ])('explains %s', (_what, spoil, expected) => {
    const o = base();
    spoil(o);
    expect(pathsAndMessages(problemsOf(text(o)))).toEqual(expected);
  });

  it('reports every problem at once, in file order', () => {
    const o = { ...base(), name: 5, robot: { x: 0, y: 0, heading: 'north' }, extra: true };
    expect(pathsAndMessages(problemsOf(text(o)))).toEqual([
      '$.extra: unknown field "extra"; allowed: format, version, name, description, walls, goals, plan, robot, goalRadius, bounds, body',
      '$.name: expected a text in double quotes, found 5',
      '$.robot.heading: expected a number, found "north"',
    ]);
  });

  it('explains invalid JSON with its line and column', () => {
    const ps = problemsOf('{\n  "format": "layerbot-world",\n  "version": 1,\n}');
    expect(ps).toEqual([
      {
        file: 'w.world.json',
        path: '$',
        message: 'not valid JSON at line 4, column 1: a comma before } is not allowed in JSON; remove the comma after the last field',
        line: 4,
        column: 1,
      },
    ]);
  });

  describe('format and version', () => {
    it('says so when a controller is opened as a world', () => {
      const controller = readFileSync(join(__dirname, '../../../examples/controllers/basic.controller.json'), 'utf8');
      expect(pathsAndMessages(problemsOf(controller))).toEqual(['$.format: this file is a Layerbot controller, not a world; open it as a controller']);
    });

    it('names the expected format when it is something else', () => {
      expect(pathsAndMessages(problemsOf(text({ ...base(), format: 'world' })))).toEqual([
        '$.format: expected "layerbot-world" (this should be a Layerbot world file), found "world"',
      ]);
      expect(pathsAndMessages(problemsOf(text({ name: 'x' })))).toEqual(['$: missing field "format": a world file starts with "format": "layerbot-world"']);
      expect(pathsAndMessages(problemsOf('[1, 2]'))).toEqual([
        '$: expected a Layerbot world: an object {"format": "layerbot-world", "version": 1, ...}, found a list of 2 items',
      ]);
    });

    it('refuses files from a newer Layerbot, and odd versions', () => {
      expect(pathsAndMessages(problemsOf(text({ ...base(), version: 2 })))).toEqual([
        '$.version: this world was made by a newer Layerbot (format version 2; this Layerbot reads versions up to 1); update Layerbot to open it',
      ]);
      expect(pathsAndMessages(problemsOf(text({ ...base(), version: '1' })))).toEqual(['$.version: expected a whole number from 1 to 1, found "1"']);
      const noVersion = base();
      delete noVersion.version;
      expect(pathsAndMessages(problemsOf(text(noVersion)))).toEqual(['$: missing field "version": expected "version": 1']);
    });
  });

  describe('world-level checks', () => {
    it('finds duplicate goal names', () => {
      const o = base();
      (o.goals as object[]).push({ name: 'a', x: 3, y: 3 });
      expect(pathsAndMessages(problemsOf(text(o)))).toEqual(['$.goals[2].name: two goals are named "a" ($.goals[0] and $.goals[2]); goal names must differ']);
    });

    it('finds plan steps that name no goal, with a guess', () => {
      const o = { ...base(), plan: ['a', 'B', 'storage'] };
      expect(pathsAndMessages(problemsOf(text(o)))).toEqual([
        '$.plan[1]: no goal is named "B" (did you mean "b"?); the goals are: a, b',
        '$.plan[2]: no goal is named "storage"; the goals are: a, b',
      ]);
      expect(pathsAndMessages(problemsOf(text({ ...base(), goals: [], plan: ['a'] })))).toEqual(['$.plan[0]: no goal is named "a"; the world has no goals']);
    });

    it('allows an empty plan and repeated steps', () => {
      expect(parseWorld(text({ ...base(), plan: [] }), 'w').ok).toBe(true);
      expect(parseWorld(text({ ...base(), plan: ['a', 'a', 'b'] }), 'w').ok).toBe(true);
    });

    it('rejects zero-length walls, which the robot could never touch', () => {
      const o = { ...base(), walls: [[[5, -5], [5, 5]], [[7, 7], [7, 7]]] };
      expect(pathsAndMessages(problemsOf(text(o)))).toEqual([
        '$.walls[1]: this wall starts and ends at the same point (7, 7), so the robot could never touch it; move one end or remove the wall',
      ]);
    });

    it('rejects a robot that starts on a wall', () => {
      const o = { ...base(), walls: [[[-5, 0], [5, 0]]] };
      expect(pathsAndMessages(problemsOf(text(o)))).toEqual(['$.robot: the robot starts on the wall $.walls[0], so its first move would crash; move the robot or the wall']);
    });

    it('checks bounds', () => {
      expect(pathsAndMessages(problemsOf(text({ ...base(), bounds: { minX: 0, minY: 0, maxX: 0, maxY: 10 } })))).toEqual(['$.bounds: minX (0) must be less than maxX (0)']);
      expect(pathsAndMessages(problemsOf(text({ ...base(), bounds: { minX: -1, minY: -1, maxX: 5, maxY: 20 } })))).toEqual([
        '$.goals[0]: the goal "a" at (10, 0) is outside the bounds; widen $.bounds or move the goal',
      ]);
      expect(parseWorld(text({ ...base(), bounds: { minX: -1, minY: -1, maxX: 11, maxY: 11 } }), 'w').ok).toBe(true);
    });
  });
});

describe('serializeWorld', () => {
  it('writes format and version first, then a fixed field order, leaving out absent fields', () => {
    const spec: WorldSpec = {
      plan: ['g'],
      goals: [{ y: 2, x: 1, name: 'g' } as never],
      walls: [],
      robot: { heading: 90, y: 0, x: 0 } as never,
      name: 'N',
    };
    expect(serializeWorld(spec)).toBe(
      [
        '{',
        '  "format": "layerbot-world",',
        '  "version": 1,',
        '  "name": "N",',
        '  "robot": { "x": 0, "y": 0, "heading": 90 },',
        '  "goals": [',
        '    { "name": "g", "x": 1, "y": 2 }',
        '  ],',
        '  "plan": ["g"],',
        '  "walls": []',
        '}',
        '',
      ].join('\n'),
    );
  });

  it('round-trips every optional field', () => {
    const spec: WorldSpec = {
      ...(base() as unknown as WorldSpec),
      description: 'd',
      goalRadius: 1.5,
      bounds: { minX: -20, minY: -20, maxX: 20, maxY: 20 },
      body: { maxSpeed: 2, whiskerLength: 3, whiskerAngle: 45 },
    };
    const r = parseWorld(serializeWorld(spec), 'w');
    expect(r.ok && r.value).toEqual({ ...spec, format: undefined, version: undefined });
  });
});
