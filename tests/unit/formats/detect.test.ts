import { detectFormat, formatProblems, parseWorld } from '../../../app/core/formats';

describe('detectFormat', () => {
  it('tells worlds, controllers and packs apart', () => {
    expect(detectFormat('{"format": "layerbot-world", "version": 1}')).toBe('world');
    expect(detectFormat('\uFEFF{"format": "layerbot-controller"}')).toBe('controller');
    expect(detectFormat('{"format": "layerbot-pack"}')).toBe('pack');
  });

  it('still tells when the JSON is broken', () => {
    expect(detectFormat('{"format": "layerbot-world", "walls": [,]}')).toBe('world');
  });

  it('says null for anything else', () => {
    expect(detectFormat('{"format": "other"}')).toBeNull();
    expect(detectFormat('[1]')).toBeNull();
    expect(detectFormat('nonsense')).toBeNull();
    expect(detectFormat('')).toBeNull();
  });
});

describe('formatProblems', () => {
  it('prints one line per problem: file, JSON path, message', () => {
    const r = parseWorld('{"format": "layerbot-world", "version": 1, "name": "x", "walls": [], "goals": [], "plan": ["a", "b"], "robot": {"x": 0, "y": 0, "heading": 0}}', 'w.json');
    if (r.ok) throw new Error('expected problems');
    expect(formatProblems(r.problems)).toBe(
      'w.json: $.plan[0]: no goal is named "a"; the world has no goals\nw.json: $.plan[1]: no goal is named "b"; the world has no goals',
    );
  });
});
