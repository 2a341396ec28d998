import { defineConfig } from 'vitest/config';

/**
 * Unit tests only: tests/e2e/ holds node:test files that drive a browser
 * against the built site (`npm run test:e2e`), which vitest must not pick up.
 */
export default defineConfig({
  test: {
    include: ['tests/unit/**/*.test.{ts,mjs}'],
    // Several tests compile a model with mathjs first, about a second on a quiet machine; on a busy
    // one that can pass vitest's default 5 s. A time limit is no assertion here: speed is the bench's.
    testTimeout: 30_000,
  },
});
