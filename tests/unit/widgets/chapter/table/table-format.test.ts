import { describe, expect, it } from 'vitest';
import { cellText, checkRows, displayNumber, headerText, resolveColumns } from '../../../../../widgets/chapter/table/table-format.ts';

describe('displayNumber (as the inspector, cells/inspect.ts)', () => {
  it('rounds away representation noise and reads back as a number', () => {
    expect(displayNumber(-3.5999999999999996)).toBe('-3.6');
    expect(displayNumber(0.1 + 0.2)).toBe('0.3');
    expect(Number(displayNumber(-23.456789012345678))).toBeCloseTo(-23.456789012345678, 10);
    expect(displayNumber(1.2345e-13, 2)).toBe('1.2e-13');
    expect(displayNumber(42)).toBe('42');
    expect(displayNumber(-0)).toBe('-0');
  });
});

describe('columns and cells', () => {
  const columns = resolveColumns(['quantity', { label: 'deflection', unit: 'rad', digits: 3, highlight: true }]);
  it('reads headers and options', () => {
    expect(columns.map(headerText)).toEqual(['quantity', 'deflection (rad)']);
    expect(columns[1]).toMatchObject({ digits: 3, highlight: true });
  });
  it('formats numbers by the column, and never shows NaN or Infinity', () => {
    expect(cellText(1.23456, columns[1])).toBe('1.23');
    expect(cellText(NaN, columns[1])).toBe('—');
    expect(cellText(-Infinity, columns[1])).toBe('−∞');
    expect(cellText('energy H', columns[0])).toBe('energy H');
    expect(cellText(undefined, columns[0])).toBe('');
  });
  it('says what is wrong with the options', () => {
    expect(() => resolveColumns([])).toThrow(/columns must be a list/);
    expect(() => resolveColumns([{ label: 'x', digits: 0 }])).toThrow(/digits must be a whole number from 1 to 17/);
    expect(() => resolveColumns([{ label: 'x', width: 3 }])).toThrow(/has no option 'width'/);
    expect(() => checkRows([[1, 2, 3]], columns)).toThrow(/rows\[0\] has 3 cells but there are 2 columns/);
    expect(() => checkRows({}, columns)).toThrow(/rows must be a list/);
  });
});
