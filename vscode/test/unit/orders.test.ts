import { describe, expect, test } from 'vitest';
import { duplicateOrders } from '../../src/analyzer/orders.ts';

describe('duplicateOrders(orders)', () => {
  test('gives every chapter that shares an order a problem naming the others', () => {
    const problems = duplicateOrders([
      { file: 'file:///book/content/a.mdx', value: 5, start: 10, end: 18 },
      { file: 'file:///book/content/b.mdx', value: 5, start: 20, end: 28 },
      { file: 'file:///book/content/c.mdx', value: 6, start: 30, end: 38 },
    ]);
    expect([...problems.keys()]).toEqual(['file:///book/content/a.mdx', 'file:///book/content/b.mdx']);
    const [a] = problems.get('file:///book/content/a.mdx')!;
    expect(a).toMatchObject({ code: 'duplicate-order', severity: 'error', start: 10, end: 18 });
    expect(a.message).toBe('order 5 is also the order of b.mdx: chapters need distinct orders (the build fails).');
    expect(a.related).toEqual([{ file: 'file:///book/content/b.mdx', start: 20, end: 28, message: 'order 5 here too' }]);
  });

  test('distinct orders give nothing', () => {
    expect(duplicateOrders([{ file: 'a', value: 1, start: 0, end: 1 }, { file: 'b', value: 2, start: 0, end: 1 }]).size).toBe(0);
  });
});
