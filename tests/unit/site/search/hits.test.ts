import { describe, expect, it } from 'vitest';
import { pageHit } from '../../../../site/search/hits.ts';

describe('site/search/hits.ts: the sections shown for a chapter', () => {
  it('keeps the sections with the most matches, in page order', () => {
    const hit = pageHit(
      {
        url: '/order-and-chaos/',
        meta: { title: 'Order and chaos' },
        excerpt: 'page excerpt',
        sub_results: [
          { title: 'Order and chaos', url: '/order-and-chaos/', excerpt: 'intro', locations: [1] },
          { title: 'The surface of section', url: '/order-and-chaos/#the-surface-of-section', excerpt: 's', locations: [20, 30] },
          { title: 'Nothing here', url: '/order-and-chaos/#nothing', excerpt: 'n', locations: [] },
          { title: 'The Lyapunov exponent', url: '/order-and-chaos/#the-lyapunov-exponent', excerpt: 'l', locations: [40, 41, 42, 43] },
          { title: 'Kepler', url: '/order-and-chaos/#kepler', excerpt: 'k', locations: [50, 51] },
        ],
      },
      2,
    );
    expect(hit).toEqual({
      title: 'Order and chaos',
      url: '/order-and-chaos/',
      sections: [
        { title: 'The surface of section', url: '/order-and-chaos/#the-surface-of-section', excerpt: 's' },
        { title: 'The Lyapunov exponent', url: '/order-and-chaos/#the-lyapunov-exponent', excerpt: 'l' },
      ],
    });
  });

  it('falls back to the page itself when no section is listed, and survives missing fields', () => {
    expect(pageHit({ url: '/about/', excerpt: 'x' })).toEqual({ title: '/about/', url: '/about/', sections: [{ title: '/about/', url: '/about/', excerpt: 'x' }] });
    expect(pageHit({ sub_results: [{ locations: [3] }] } as never)).toEqual({ title: '#', url: '#', sections: [{ title: '#', url: '#', excerpt: '' }] });
  });
});
