/**
 * The processor time of a tree of processes, Chromium's included, by sampling /proc (Linux; elsewhere it
 * reports nothing).
 *
 * GNU time, and a process's own rusage, count a child's time only once it has been waited for by its parent,
 * and so on up to the process measured. Chromium's renderers are children of its zygote, which is not waited
 * for when the browser is closed: their time, most of an e2e file's, never reaches the test's tree. Sampled
 * here instead, every process below `root` is read every `everyMs` for its own time (user + system), the
 * largest value seen kept, and summed by the label that `labelOf` gives it from its own command line or its
 * nearest ancestor's. A process that lives less than one interval, or the time a process spends after its last
 * sample, is missed: the sums are lower bounds, close ones for processes that live for seconds.
 */
import { readdirSync, readFileSync } from 'node:fs';

/** Clock ticks per second of /proc/<pid>/stat's times: 100 on every Linux that Node runs on. */
const TICKS = 100;

/** Each process's parent, own processor time (s) and command line, now. */
function processes() {
  const found = new Map();
  let names;
  try {
    names = readdirSync('/proc');
  } catch {
    return found;
  }
  for (const name of names) {
    if (!/^\d+$/.test(name)) continue;
    try {
      const stat = readFileSync(`/proc/${name}/stat`, 'utf8');
      // The command's name, in parentheses, may hold spaces: the fields are counted from its closing one.
      const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
      found.set(Number(name), {
        parent: Number(fields[1]),
        seconds: (Number(fields[11]) + Number(fields[12])) / TICKS,
        command: readFileSync(`/proc/${name}/cmdline`, 'utf8').replaceAll('\0', ' '),
      });
    } catch {
      // Ended while being read.
    }
  }
  return found;
}

/**
 * Starts sampling the processes below `root` (a pid). `labelOf(command, pid)` names what a process's time
 * counts for, or returns undefined to ask its parent; processes with no label up to `root` count for `root`'s own
 * label, `fallback`. `stop()` takes a last sample and returns the seconds by label.
 * @param {number} root
 * @param {{ labelOf?: (command: string, pid: number) => string | undefined, fallback?: string, everyMs?: number }} [options]
 */
export function watchProcessCpu(root, { labelOf = () => undefined, fallback = 'all', everyMs = 2000 } = {}) {
  /** @type {Map<number, { label: string, seconds: number, command: string }>} */
  const seen = new Map();
  const sample = () => {
    const now = processes();
    for (const [pid, p] of now) {
      let label;
      let below = false;
      for (let q = pid, hops = 0; q > 1 && hops < 64; hops++) {
        const at = now.get(q);
        if (!at) break;
        label ??= q === root ? fallback : labelOf(at.command, q);
        if (q === root) {
          below = true;
          break;
        }
        q = at.parent;
      }
      if (!below) continue;
      const before = seen.get(pid);
      // A pid reused by another process starts again from its own time.
      if (!before || before.command !== p.command) seen.set(pid, { label: label ?? fallback, seconds: p.seconds, command: p.command });
      else before.seconds = Math.max(before.seconds, p.seconds);
    }
  };
  sample();
  const timer = setInterval(sample, everyMs);
  timer.unref();
  return {
    stop() {
      clearInterval(timer);
      sample();
      /** @type {Map<string, number>} */
      const byLabel = new Map();
      for (const { label, seconds } of seen.values()) byLabel.set(label, (byLabel.get(label) ?? 0) + seconds);
      return byLabel;
    },
  };
}
