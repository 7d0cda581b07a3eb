import { parseJsonText } from '../../../app/core/formats/json';

function syntaxProblem(text: string) {
  const r = parseJsonText(text, 'f.json');
  if (r.ok) throw new Error('expected a problem');
  expect(r.problems).toHaveLength(1);
  return r.problems[0];
}

describe('parseJsonText', () => {
  it('reads what JSON.parse reads', () => {
    const text = '{"a": [1, -2.5e3, true, false, null, "x\\n\\u00e9"], "b": {"c": {}}, "d": []}';
    const r = parseJsonText(text, 'f.json');
    expect(r.ok && r.value.value).toEqual(JSON.parse(text));
  });

  it('remembers where each value starts', () => {
    const r = parseJsonText('{\n  "goals": [\n    {"name": "a"}\n  ]\n}', 'f.json');
    if (!r.ok) throw new Error('parse failed');
    expect(r.value.positionOf('$.goals')).toEqual({ line: 2, column: 12 });
    expect(r.value.positionOf('$.goals[0].name')).toEqual({ line: 3, column: 14 });
    expect(r.value.positionOf('$.nothing')).toBeUndefined();
  });

  it('accepts a byte-order mark and keeps columns as the editor shows them', () => {
    const r = parseJsonText('\uFEFF{"a": 1}', 'f.json');
    expect(r.ok && r.value.value).toEqual({ a: 1 });
  });

  it('makes "__proto__" an ordinary field, never a prototype', () => {
    const r = parseJsonText('{"__proto__": {"polluted": true}}', 'f.json');
    if (!r.ok) throw new Error('parse failed');
    const v = r.value.value as Record<string, unknown>;
    expect(Object.getPrototypeOf(v)).toBe(Object.prototype);
    expect(Object.keys(v)).toEqual(['__proto__']);
    expect(({} as Record<string, unknown>).polluted).toBeUndefined();
  });

  it.each([
    ['', 1, 1, '$', 'the file is empty'],
    ['   \n', 2, 1, '$', 'the file is empty'],
    ['{"a": 1,}', 1, 9, '$', 'a comma before } is not allowed'],
    ['{"a": [1, 2,]}', 1, 13, '$.a', 'a comma before ] is not allowed'],
    ["{'a': 1}", 1, 2, '$', 'double quotes'],
    ['{"a": \'x\'}', 1, 7, '$.a', 'not single quotes'],
    ['{a: 1}', 1, 2, '$', 'write "a"'],
    ['{"a": 1\n "b": 2}', 2, 2, '$', 'a comma is missing after the value of "a"'],
    ['{"a": [1 2]}', 1, 10, '$.a[0]', 'a comma is missing?'],
    ['{"a" 1}', 1, 6, '$.a', 'expected a colon'],
    ['{"a": "x\ny"}', 1, 7, '$.a', 'no closing double quote'],
    ['{"a": "x', 1, 7, '$.a', 'no closing double quote'],
    ['{"a": "\\q"}', 1, 8, '$.a', 'not a valid escape'],
    ['{"a": 01}', 1, 7, '$.a', '"01" is not a valid JSON number'],
    ['{"a": 1.}', 1, 7, '$.a', 'not a valid JSON number'],
    ['{"a": NaN}', 1, 7, '$.a', 'expected a value'],
    ['{"a": True}', 1, 7, '$.a', 'lower case'],
    ['// note\n{}', 1, 1, '$', 'JSON does not allow comments'],
    ['{"a": 1 /* x */}', 1, 9, '$', 'JSON does not allow comments'],
    ['{"a": 1}\n}', 2, 1, '$', 'unexpected text after the end'],
    ['{"a": [1, 2', 1, 7, '$.a', 'this list is never closed'],
    ['{\n"a": {"b": 1', 2, 6, '$.a', 'this object is never closed'],
    ['{"a": [1,,2]}', 1, 10, '$.a[1]', 'two commas in a row'],
  ])('explains %j at line %i, column %i', (text, line, column, path, words) => {
    const p = syntaxProblem(text);
    expect(p).toMatchObject({ file: 'f.json', path, line, column });
    expect(p.message).toContain(`not valid JSON at line ${line}, column ${column}: `);
    expect(p.message).toContain(words);
  });

  it('rejects a field written twice, which JSON.parse would hide', () => {
    const r = parseJsonText('{\n  "name": "a",\n  "x": 1,\n  "name": "b"\n}', 'f.json');
    expect(r.ok).toBe(false);
    if (r.ok) return;
    expect(r.problems).toEqual([
      {
        file: 'f.json',
        path: '$.name',
        message: 'the field "name" is written twice in this object (on line 2 and again on line 4); keep only one',
        line: 4,
        column: 3,
      },
    ]);
  });

  it('reads deeply nested block JSON', () => {
    let text = '1';
    for (let i = 0; i < 2000; i++) text = `{"next": {"block": ${text}}}`;
    const r = parseJsonText(text, 'f.json');
    expect(r.ok).toBe(true);
  });
});
