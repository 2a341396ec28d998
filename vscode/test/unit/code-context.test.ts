import { describe, expect, test } from 'vitest';
import { codeContext } from '../../src/analyzer/code-context.ts';

describe('codeContext(textBeforeCursor)', () => {
  test('at a key of the options object of a call: the callee, the argument and the keys already written', () => {
    expect(codeContext("simulator({ model: m, views: ['time', 'phase'], ini")).toEqual({
      kind: 'key',
      prefix: 'ini',
      owner: { callee: 'simulator', argument: 0, path: [] },
      present: ['model', 'views'],
    });
  });

  test('inside an options-valued option: the path of keys', () => {
    const context = codeContext('simulator({\n  timePlot: { height: 200, ');
    expect(context).toMatchObject({ kind: 'key', prefix: '', owner: { callee: 'simulator', argument: 0, path: ['timePlot'] } });
  });

  test('the second argument of a constructor', () => {
    expect(codeContext('run = new Simulation(model, { dt: 1e-3, ')).toMatchObject({ kind: 'key', owner: { callee: 'Simulation', argument: 1, path: [] } });
  });

  test('at a value: a name, not a key', () => {
    expect(codeContext('simulator({ model: pend')).toEqual({ kind: 'name', prefix: 'pend' });
    expect(codeContext('simulator({ initial: [0.5, pendulumSt')).toEqual({ kind: 'name', prefix: 'pendulumSt' });
  });

  test('after a closed options object the context is the enclosing one', () => {
    expect(codeContext('x = f(simulator({ model }), can')).toEqual({ kind: 'name', prefix: 'can' });
  });

  test('in a block, an arrow function body or a bare object: names', () => {
    expect(codeContext('periodCheck = {\n  const T = 2 * PI / ome')).toEqual({ kind: 'name', prefix: 'ome' });
    expect(codeContext('simulator({ derived: { I: (t, x, H) => { return H / ome')).toEqual({ kind: 'name', prefix: 'ome' });
    expect(codeContext('params = ({ omega: 1, ')).toEqual({ kind: 'name', prefix: '' });
  });

  test('in a string, a comment or after a dot: nothing', () => {
    expect(codeContext("simulator({ label: 'A pend")).toEqual({ kind: 'none' });
    expect(codeContext('simulator({ // the model\n  // mod')).toEqual({ kind: 'none' });
    expect(codeContext('x = Math.')).toEqual({ kind: 'none' });
    expect(codeContext('x = run.record.col')).toEqual({ kind: 'none' });
  });

  test('a spread is not a member access', () => {
    expect(codeContext('simulator({ ...bas')).toMatchObject({ kind: 'key', prefix: 'bas' });
  });

  test('strings and comments with brackets in them do not unbalance the scan', () => {
    expect(codeContext("theoryCheck({ label: 'a (b', method: \"{\", /* ) */ to")).toMatchObject({ kind: 'key', owner: { callee: 'theoryCheck' } });
  });

  test('a keyword before a paren calls nothing', () => {
    expect(codeContext('x = { if ({ a')).toEqual({ kind: 'name', prefix: 'a' });
  });
});
