import { describe, expect, it } from 'vitest';
import { contentSecurityPolicy, scriptHash } from '../../../site/lib/csp.ts';

const directives = (policy: string) => new Map(policy.split('; ').map((d) => [d.split(' ')[0], d.split(' ').slice(1)] as const));

describe('site/lib/csp.ts: the policy every page carries in a <meta> tag', () => {
  it('allows the page’s own inline scripts by hash, and no other', () => {
    const policy = directives(contentSecurityPolicy(['console.log(1)']));
    expect(policy.get('script-src')).toEqual(["'self'", "'unsafe-eval'", scriptHash('console.log(1)')]);
  });

  it('frames nothing itself, and leaves out frame-ancestors, which a <meta> policy cannot carry: embed pages may be framed by any site', () => {
    const policy = directives(contentSecurityPolicy([]));
    expect(policy.get('frame-src')).toEqual(["'none'"]);
    expect(policy.has('frame-ancestors')).toBe(false);
  });
});
