#!/usr/bin/env node
/**
 * `npm test`: every stage of the suite, each run to its end and reported
 * whatever the others do, then a table of their statuses and times; the exit
 * status is 1 if any stage failed or could not run.
 *
 *   node tests/run.mjs                 every stage
 *   node tests/run.mjs unit e2e        only these (a stage's prerequisites are then taken as done)
 *   node tests/run.mjs --list          the stages and what each runs
 *
 * Stages run side by side where that shortens the wall time on two cores
 * without one starving another: the site's build, then the end-to-end
 * tests (browsers mostly waiting on pages), in one lane; the type check,
 * then the base-path build the e2e lane will serve, the unit tests and the
 * VS Code extension's tests beside one another in the other, the unit tests
 * at a lower priority, taking what the first lane leaves idle. A stage
 * that needs another's result (e2e needs the build) is not run when that one
 * failed, and is reported as blocked. Each stage's output is printed whole
 * when it ends, so that two stages' lines never interleave, and is kept in
 * the log folder named at the end (PHASEBOOK_TEST_LOGS, or a fresh temp dir).
 */
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { availableParallelism, loadavg, setPriority, tmpdir } from 'node:os';
import { delimiter, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { watchProcessCpu } from './process-cpu.mjs';

const ROOT = fileURLToPath(new URL('..', import.meta.url));

/**
 * `needs`: stages whose success this one requires (else it is blocked);
 * `after`: stages it waits for, pass or fail, only so as not to compete with them for the cores;
 * `background`: pure computation, run at a lower priority (nice 10), so that the build, on which e2e
 * waits, and the browsers of e2e, whose pages wait on frames and timers, have the cores first, and these
 * take what the others leave idle.
 * @type {{ name: string, command: string[], needs?: string[], after?: string[], background?: boolean, about: string }[]}
 */
const STAGES = [
  { name: 'build', command: ['astro', 'build'], about: 'the site, into dist/' },
  { name: 'e2e', command: ['npm', 'run', '--silent', 'test:e2e'], needs: ['build'], about: 'end-to-end tests in headless Chromium against dist/' },
  { name: 'typecheck', command: ['tsc', '--noEmit'], background: true, about: 'the type check' },
  // The site built again under a base path, for the e2e files that serve it there (tests/e2e/base-build.mjs), made
  // here beside the e2e lane instead of inside it, where two files would wait on it for a minute; at the usual
  // priority, since those files wait for it. After the site's build, not beside it: Astro renders the pages of a
  // build whose output is outside the project (PHASEBOOK_OUT_DIR=/tmp/…) from a bundle in the project's .astro/,
  // which two such builds at once would share.
  { name: 'build:base', command: ['node', 'tests/e2e/base-build.mjs'], after: ['build'], about: 'the site under the base path /phasebook/, beside dist/' },
  { name: 'unit', command: ['vitest', 'run'], after: ['typecheck'], background: true, about: 'the unit tests (vitest)' },
  { name: 'vscode:setup', command: ['npm', 'run', '--silent', 'setup:vscode'], about: "the extension's own dependencies (npm install in vscode/)" },
  // The extension's host suite mostly waits (on VS Code's web build and its browser), so it runs beside the unit
  // tests rather than after them; its unit tests follow it, not beside it, since both write the extension's
  // catalogue (vscode/build/build.ts), and run beside the book's unit tests.
  { name: 'vscode:host', command: ['npm', 'run', '--silent', 'test:vscode:host'], needs: ['vscode:setup'], after: ['typecheck'], about: "the extension's suite in a VS Code web build" },
  { name: 'vscode:unit', command: ['npm', 'run', '--silent', 'test:vscode:unit'], needs: ['vscode:setup'], after: ['vscode:host'], background: true, about: "the extension's build, type check and unit tests" },
];

const args = process.argv.slice(2);
if (args.includes('--list')) {
  for (const s of STAGES) console.log(`${s.name.padEnd(12)} ${s.command.join(' ')}  (${s.about})`);
  process.exit(0);
}
const unknown = args.filter((a) => !STAGES.some((s) => s.name === a));
if (unknown.length) {
  console.error(`tests/run.mjs: no stage ${unknown.join(', ')}; the stages are ${STAGES.map((s) => s.name).join(', ')}`);
  process.exit(2);
}
const chosen = args.length ? STAGES.filter((s) => args.includes(s.name)) : STAGES;
const isChosen = (name) => chosen.some((s) => s.name === name);

const logs = process.env.PHASEBOOK_TEST_LOGS ?? mkdtempSync(join(tmpdir(), 'phasebook-test-logs-'));
mkdirSync(logs, { recursive: true });
const env = { ...process.env, PATH: [join(ROOT, 'node_modules', '.bin'), process.env.PATH].join(delimiter), ASTRO_TELEMETRY_DISABLED: '1', FORCE_COLOR: process.env.FORCE_COLOR ?? '0' };
const began = Date.now();
console.log(`tests/run.mjs: ${chosen.map((s) => s.name).join(', ')} on ${availableParallelism()} cores, load average ${loadavg().map((l) => l.toFixed(2)).join(', ')}`);
const clock = (ms) => `${Math.floor(ms / 60_000)}:${String(Math.floor((ms % 60_000) / 1000)).padStart(2, '0')}`;
const say = (line) => console.log(`[${clock(Date.now() - began)}] ${line}`);

/** The load average over the last minute, as `uptime` gives it: timings mean little without it. */
const load = () => loadavg()[0].toFixed(2);

/** @type {Map<string, { status: 'passed' | 'failed' | 'blocked', startedAt: number, ms: number, cpu?: number, load: string, note?: string }>} */
const results = new Map();
/** @type {Map<string, import('node:child_process').ChildProcess>} */
const running = new Map();

/**
 * GNU time, where there is one, to report the processor time each stage took (its own and its children's):
 * beside the wall time and the load, it tells a slow stage from a starved one. It misses what is never waited
 * for, Chromium's renderers above all (most of e2e's time), which /proc sampled every two seconds sees; that
 * misses processes shorter than that (the CLI runs of the unit tests). Each is a lower bound: the table gives
 * the larger.
 */
/** @type {Map<number, string>} each stage's process, by its pid */
const stageOf = new Map();
const sampled = watchProcessCpu(process.pid, { labelOf: (command, pid) => stageOf.get(pid), fallback: 'tests/run.mjs' });
const TIME = existsSync('/usr/bin/time') ? '/usr/bin/time' : null;
/** nice(1), so that a background stage's whole tree starts at the lower priority; else the stage's own process is lowered once started. */
const NICE = existsSync('/usr/bin/nice') ? '/usr/bin/nice' : null;

/** Runs one stage to its end: its output goes to its log file and is printed whole when it ends. */
function run(stage) {
  const startedAt = Date.now();
  say(`▶ ${stage.name}: ${stage.command.join(' ')}`);
  const cpuFile = join(logs, `${stage.name.replace(':', '-')}.cpu`);
  return new Promise((resolve) => {
    const niced = stage.background && NICE ? [NICE, '-n', '10', ...stage.command] : stage.command;
    const [command, ...rest] = TIME ? [TIME, '-q', '-f', '%U %S', '-o', cpuFile, ...niced] : niced;
    // Its own process group, so that an interrupted run takes the stage's whole tree down with it.
    const child = spawn(command, rest, { cwd: ROOT, env, stdio: ['ignore', 'pipe', 'pipe'], detached: process.platform !== 'win32' });
    running.set(stage.name, child);
    if (child.pid) stageOf.set(child.pid, stage.name);
    if (stage.background && !NICE && child.pid) {
      try {
        setPriority(child.pid, 10);
      } catch {
        // Not allowed here: it runs at the usual priority.
      }
    }
    const output = [];
    child.stdout.on('data', (chunk) => output.push(chunk));
    child.stderr.on('data', (chunk) => output.push(chunk));
    const finish = (code, note) => {
      running.delete(stage.name);
      const ms = Date.now() - startedAt;
      const text = Buffer.concat(output).toString();
      writeFileSync(join(logs, `${stage.name.replace(':', '-')}.log`), text);
      const status = code === 0 ? 'passed' : 'failed';
      let cpu = NaN;
      try {
        const [user, system] = readFileSync(cpuFile, 'utf8').trim().split('\n').pop().split(' ').map(Number);
        cpu = user + system;
      } catch {
        // No GNU time, or the stage never started.
      }
      console.log(`\n──── ${stage.name} (${stage.command.join(' ')}) ────\n${text.trimEnd()}\n──── ${stage.name}: ${status} in ${clock(ms)}${note ? ` (${note})` : ''} ────\n`);
      say(`${status === 'passed' ? '✔' : '✘'} ${stage.name} ${status} in ${clock(ms)} (load average ${load()})`);
      results.set(stage.name, { status, startedAt: startedAt - began, ms, cpu, load: load(), note });
      resolve();
    };
    child.on('error', (error) => finish(1, error.message));
    child.on('close', (code, signal) => finish(code ?? 1, signal ? `ended by ${signal}` : undefined));
  });
}

/** Starts every stage whose waits are over; resolves when all have ended. */
async function schedule() {
  const pending = new Set(chosen.map((s) => s.name));
  const active = new Map();
  while (pending.size || active.size) {
    for (const name of [...pending]) {
      const stage = STAGES.find((s) => s.name === name);
      const waits = [...(stage.needs ?? []), ...(stage.after ?? [])].filter(isChosen);
      if (!waits.every((w) => results.has(w))) continue;
      pending.delete(name);
      const failed = (stage.needs ?? []).filter((w) => isChosen(w) && results.get(w).status !== 'passed');
      if (failed.length) {
        const note = `not run: ${failed.join(', ')} did not pass`;
        results.set(name, { status: 'blocked', startedAt: Date.now() - began, ms: 0, load: load(), note });
        say(`✘ ${name} blocked (${note})`);
        continue;
      }
      active.set(name, run(stage).then(() => active.delete(name)));
    }
    if (active.size) await Promise.race(active.values());
    else if (pending.size) throw new Error(`stages waiting on each other: ${[...pending].join(', ')}`);
  }
}

// A heartbeat while stages run, so that a long quiet stage is not mistaken for a hung run.
const heartbeat = setInterval(() => running.size && say(`… running: ${[...running.keys()].join(', ')}`), 60_000);

for (const signal of ['SIGINT', 'SIGTERM']) {
  process.on(signal, () => {
    for (const child of running.values()) {
      try {
        process.kill(-child.pid, signal);
      } catch {
        child.kill(signal);
      }
    }
    process.exit(130);
  });
}

await schedule();
clearInterval(heartbeat);
const sampledSeconds = sampled.stop();

const rows = chosen.map((s) => {
  const r = results.get(s.name);
  const cpu = Math.max(Number.isFinite(r.cpu) ? r.cpu : 0, sampledSeconds.get(s.name) ?? 0);
  return [s.name, r.status, r.status === 'blocked' ? '—' : clock(r.ms), r.status === 'blocked' ? '—' : clock(r.startedAt), cpu > 0 ? clock(1000 * cpu) : '—', r.load, r.note ?? ''];
});
const head = ['stage', 'status', 'time', 'started', 'cpu', 'load at end', ''];
const widths = head.map((h, i) => Math.max(h.length, ...rows.map((r) => r[i].length)));
const line = (cells) => cells.map((c, i) => c.padEnd(widths[i])).join('  ').trimEnd();
console.log(`\n${line(head)}\n${line(widths.map((w) => '─'.repeat(w)))}\n${rows.map(line).join('\n')}`);
const bad = rows.filter((r) => r[1] !== 'passed');
console.log(`\n${bad.length ? `${bad.length} of ${rows.length} stages did not pass` : `all ${rows.length} stages passed`} in ${clock(Date.now() - began)} (load average ${loadavg().map((l) => l.toFixed(2)).join(', ')}); logs in ${logs}`);
process.exit(bad.length ? 1 : 0);
