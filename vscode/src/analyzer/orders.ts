/**
 * The one check that needs the whole book: two chapters may not share an
 * `order` (site/lib/chapters.ts fails the build). Each chapter that shares
 * one gets a problem on its `order:` line naming the others.
 */
import type { Problem } from './problems.ts';

export interface ChapterOrder {
  /** The file's key (a URI string). */
  readonly file: string;
  readonly value: number;
  readonly start: number;
  readonly end: number;
}

function fileName(file: string): string {
  return decodeURIComponent(file.slice(file.lastIndexOf('/') + 1));
}

/** Problems by file, for the files whose order another file uses too. */
export function duplicateOrders(orders: readonly ChapterOrder[]): Map<string, Problem[]> {
  const byValue = new Map<number, ChapterOrder[]>();
  for (const order of orders) byValue.set(order.value, [...(byValue.get(order.value) ?? []), order]);
  const problems = new Map<string, Problem[]>();
  for (const [value, sharing] of byValue) {
    if (sharing.length < 2) continue;
    for (const order of sharing) {
      const others = sharing.filter((other) => other !== order);
      problems.set(order.file, [
        ...(problems.get(order.file) ?? []),
        {
          code: 'duplicate-order',
          severity: 'error',
          message: `order ${value} is also the order of ${others.map((o) => fileName(o.file)).join(', ')}: chapters need distinct orders (the build fails).`,
          start: order.start,
          end: order.end,
          related: others.map((other) => ({ file: other.file, start: other.start, end: other.end, message: `order ${value} here too` })),
        },
      ]);
    }
  }
  return problems;
}
