/**
 * A progress bar on stderr, shown only on a terminal and only once a run has
 * taken more than a second, so quick runs and pipelines stay quiet. The time
 * left is estimated from the pace so far.
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
      const eta = fraction > 0 && fraction < 1 ? `  ETA ${duration(((now - start) * (1 - fraction)) / fraction)}` : '';
      stream.write(`\r${bar} ${(fraction * 100).toFixed(0).padStart(3)}%  ${label}${eta}\x1b[K`);
    },
    done(): void {
      if (shown) stream.write('\r\x1b[K');
    },
  };
}

/** Milliseconds as a person reads a time left: 8 s, 4 min 10 s, 2 h 5 min. */
export function duration(ms: number): string {
  const s = Math.ceil(ms / 1000);
  if (s < 60) return `${s} s`;
  if (s < 3600) return `${Math.floor(s / 60)} min ${s % 60} s`;
  return `${Math.floor(s / 3600)} h ${Math.floor((s % 3600) / 60)} min`;
}
