#!/usr/bin/env node
/**
 * `npm run test:e2e`: every e2e file against the built site, one per core at a time (each file its own server
 * and browser), the longest first, then a table of each file's wall time and processor time (its browser's
 * included, sampled: tests/process-cpu.mjs), longest first.
 *
 *   node tests/e2e/run.mjs                     every file
 *   node tests/e2e/run.mjs lazy every-page     only the files whose names contain one of these
 *
 * `node --test` starts the files of a folder in the order of their names, so a long file whose name comes
 * late started last and alone set the suite's end: in the last quiet run the phone sweep, started halfway,
 * ran on for minutes after the other slots had emptied. Started first, the long files run beside the many
 * short ones, which fill the other slots around them. LONGEST is an order, not a measure: a file missing
 * from it runs after them, and a name in it that matches no file is refused, so that the list cannot rot
 * silently. The table at the end is what to update it from.
 */
import { readdirSync } from 'node:fs';
import { availableParallelism } from 'node:os';
import { join } from 'node:path';
import { run } from 'node:test';
import { spec } from 'node:test/reporters';
import { fileURLToPath } from 'node:url';
import { watchProcessCpu } from '../process-cpu.mjs';

const HERE = fileURLToPath(new URL('.', import.meta.url));

/**
 * The files that take longest (wall time, from the table this prints), in that order; base-crawl and base-path
 * not among the first four, since they serve the base-path build, which npm test makes once the site's is done.
 */
const LONGEST = [
  'every-page-phone',
  'book-pdf',
  'instant-start',
  'every-page-desk',
  'base-crawl',
  'interactions',
  'fault-proof',
  'untrusted-code',
  'check-sweeps',
  'persistence',
  'plots-read',
  'math-fonts',
  'exercises',
  'build',
  'cells',
  'lazy',
  'share',
  'finding-the-way',
];

/**
 * A limit per file, against a hang only: the longest file takes about 4½ minutes alone on a quiet two-core
 * machine, and must still pass on one four times as loaded.
 */
const TIMEOUT_MS = 2_400_000;
/**
 * Files at a time: one per core (PHASEBOOK_E2E_CONCURRENCY to choose). The renderers are what take the
 * processor, and a page's work grows with the time it stays open (its simulators draw every frame, its
 * timers fire), so files beyond the cores made every file slower and the suite's processor time larger: four
 * at a time on two cores took 57 processor-minutes where two at a time took 44, for the same tests.
 */
const CONCURRENCY = Number(process.env.PHASEBOOK_E2E_CONCURRENCY) || Math.max(2, availableParallelism());

const every = readdirSync(HERE).filter((name) => name.endsWith('.test.mjs')).sort();
const stem = (name) => name.replace(/\.test\.mjs$/, '');
const unknown = LONGEST.filter((name) => !every.some((file) => stem(file) === name));
if (unknown.length) {
  console.error(`tests/e2e/run.mjs: LONGEST names no file ${unknown.join(', ')}`);
  process.exit(2);
}
const rank = (file) => {
  const i = LONGEST.indexOf(stem(file));
  return i === -1 ? LONGEST.length : i;
};
const wanted = process.argv.slice(2);
const files = every.filter((file) => !wanted.length || wanted.some((w) => file.includes(w))).sort((a, b) => rank(a) - rank(b) || a.localeCompare(b));
if (!files.length) {
  console.error(`tests/e2e/run.mjs: no e2e file matches ${wanted.join(', ')}`);
  process.exit(2);
}

/** @type {Map<string, number>} each file's wall time, ms, as node:test measured it from its start */
const wall = new Map();
const cpu = watchProcessCpu(process.pid, { labelOf: (command) => command.match(/tests\/e2e\/([\w.-]+)\.test\.mjs/)?.[1], fallback: 'the runner' });
const stream = run({ files: files.map((file) => join(HERE, file)), concurrency: CONCURRENCY, timeout: TIMEOUT_MS });
stream.on('test:fail', () => (process.exitCode = 1));
stream.on('test:complete', (event) => {
  if (event.nesting === 0 && event.name === event.file) wall.set(event.file, event.details.duration_ms);
});
const reported = stream.compose(new spec());
reported.pipe(process.stdout, { end: false });
reported.on('end', () => {
  const seconds = cpu.stop();
  const rows = [...wall].sort((a, b) => b[1] - a[1]);
  const clock = (ms) => `${Math.floor(ms / 60_000)}:${String(Math.floor((ms % 60_000) / 1000)).padStart(2, '0')}`;
  const cpuOf = (name) => (seconds.has(name) ? clock(1000 * seconds.get(name)) : '—');
  console.log(`\neach file's wall time and processor time, its browser's included (${CONCURRENCY} files at a time, the longest first):`);
  console.log('   wall    cpu  file');
  for (const [file, ms] of rows) {
    const name = stem(file.slice(HERE.length));
    console.log(`  ${clock(ms).padStart(5)}  ${cpuOf(name).padStart(5)}  ${name}`);
  }
  const total = [...seconds.values()].reduce((sum, s) => sum + s, 0);
  console.log(`  total processor time ${clock(1000 * total)}, of which the runner's own ${cpuOf('the runner')}`);
});
