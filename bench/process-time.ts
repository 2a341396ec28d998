/**
 * Whole-process timing for bench/cli.ts: wall time from spawn to exit, the
 * way a user waits for a command, start-up included.
 */
import { spawnSync } from 'node:child_process';

export interface Command {
  /** the row's label */
  name: string;
  argv: readonly string[];
  env?: NodeJS.ProcessEnv;
  cwd?: string;
}

export interface Timing {
  median: number;
  best: number;
  /** stdout of the last run, for checking what the process computed */
  stdout: string;
}

/** Runs a command to completion; a failure stops the benchmark with the command's own message. */
export function runOnce(command: Command): { seconds: number; stdout: string } {
  const [file, ...args] = command.argv;
  const start = performance.now();
  const result = spawnSync(file, args, {
    cwd: command.cwd,
    env: { ...process.env, ...command.env },
    encoding: 'utf8',
    maxBuffer: 1 << 28,
  });
  const seconds = (performance.now() - start) / 1000;
  if (result.status !== 0) {
    throw new Error(`${command.name} failed (status ${result.status}): ${result.stderr || result.error?.message}`);
  }
  return { seconds, stdout: result.stdout };
}

/**
 * Times several commands over `rounds` rounds, each round running every
 * command once in turn, so that a change in the machine's load during the
 * benchmark shifts all of them alike rather than whichever ran last.
 */
export function timeInterleaved(commands: readonly Command[], rounds: number): Timing[] {
  const times = commands.map(() => [] as number[]);
  const stdout = commands.map(() => '');
  for (let r = 0; r < rounds; r++) {
    commands.forEach((command, i) => {
      const run = runOnce(command);
      times[i].push(run.seconds);
      stdout[i] = run.stdout;
    });
  }
  return times.map((list, i) => {
    const sorted = [...list].sort((a, b) => a - b);
    return { median: sorted[Math.floor(sorted.length / 2)], best: sorted[0], stdout: stdout[i] };
  });
}
