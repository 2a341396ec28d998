/**
 * A progress bar on stderr, shown only on a terminal and only once a run has
 * taken more than a second, so quick runs and pipelines stay quiet.
 */
export function progressBar(stream: NodeJS.WriteStream = process.stderr, delayMs = 1000) {
  const start = performance.now();
  const enabled = Boolean(stream.isTTY);
  let shown = false;
  let last = 0;
  return {
    update(fraction: number, label: string): void {
      if (!enabled) return;
      const now = performance.now();
      if (now - start < delayMs || now - last < 100) return;
      last = now;
      shown = true;
      const width = 30;
      const filled = Math.round(Math.min(1, fraction) * width);
      const bar = '█'.repeat(filled) + '░'.repeat(width - filled);
      stream.write(`\r${bar} ${(fraction * 100).toFixed(0).padStart(3)}%  ${label}\x1b[K`);
    },
    done(): void {
      if (shown) stream.write('\r\x1b[K');
    },
  };
}
