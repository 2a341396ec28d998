import { BlowUpError, InputError, VERSION } from '../core/index.ts';
import { Interrupted } from './interrupt.ts';
import { OutputError } from './output/output-error.ts';
import { byteSize, count, OUTPUT_LIMIT, STEP_LIMIT } from './dataset/size.ts';
import { COMMANDS } from './options/commands.ts';
import { simulate } from './commands/simulate.ts';
import { spectrumCommand } from './commands/spectrum.ts';
import { mergeCommand } from './commands/merge.ts';
import { reproduceCommand } from './commands/reproduce.ts';
import { commandHelp, synopsis } from './options/usage.ts';

const USAGE = `phasebook ${VERSION}: simulate Hamiltonian systems and analyse their spectra

${COMMANDS.flatMap(synopsis).map((line) => `  ${line}`).join('\n')}

phasebook COMMAND --help says what each option of COMMAND does.

H is a math expression (p^2/2 + omega0^2*q^2/2 + alpha*q^3) or a JS arrow
function ((t, x) => x[1]**2/2 + x[0]**2/2); --param values are visible to both.
A vector field ((t, x, dxdt) => { dxdt[0] = x[1]; dxdt[1] = -x[0]; }) is
integrated as written. Compiled models are cached in $PHASEBOOK_CACHE_DIR,
else $XDG_CACHE_HOME/phasebook/models, else ~/.cache/phasebook/models.

Many trajectories run in one process, on --workers threads (by default every
core, once a run has more than 5e6 steps to share), with the same bytes out
whatever their number. --energy E solves
H = E for one momentum, the first (p, p0) unless --solve-for names another,
within its --box range; a drawn point with no solution there is dropped and
another drawn. --shard i/n computes the i-th of n slices of the set, and
merge joins the slices into the file the whole run writes. reproduce runs a
JSON, NPZ or Parquet file again from its meta and compares every number.

JavaScript that does not translate to an expression (an opaque H, a vector
field) runs in a sandbox: a Node process with no file writes, no processes
and no environment. reproduce runs a file's JavaScript only with
--trust-code; without it, it shows the code and stops.

A run of more than ${count(STEP_LIMIT)} steps or about ${byteSize(OUTPUT_LIMIT)} of output is refused unless
--force is given. --output FILE appears only when complete; Ctrl-C (SIGINT) or
SIGTERM removes the partial file and exits with status 130 or 143.
`;

/**
 * Runs one command. Any problem with the input, or with writing the output
 * (a full disk, a read-only directory), ends in one line on stderr and exit
 * status 2: a user mistake deserves a sentence, not a stack trace. A run
 * stopped by a signal ends in one line and the shell's status for it.
 */
export async function main(argv: readonly string[]): Promise<number> {
  const [command, ...rest] = argv;
  const declared = COMMANDS.find((c) => c.name === command);
  if (declared && rest.includes('--help')) {
    process.stdout.write(commandHelp(declared));
    return 0;
  }
  try {
    switch (command) {
      case 'simulate':
        await simulate(rest);
        return 0;
      case 'spectrum':
        process.stdout.write(await spectrumCommand(rest));
        return 0;
      case 'merge':
        process.stdout.write(await mergeCommand(rest));
        return 0;
      case 'reproduce': {
        const { text, status } = await reproduceCommand(rest);
        process.stdout.write(text);
        return status;
      }
      case undefined:
      case '--help':
      case 'help':
        process.stdout.write(USAGE);
        return command === undefined ? 2 : 0;
      case '--version':
        process.stdout.write(`${VERSION}\n`);
        return 0;
      default:
        throw new InputError(`unknown command "${command}"; use simulate, spectrum, merge or reproduce (phasebook --help)`);
    }
  } catch (error) {
    if (error instanceof Interrupted) {
      process.stderr.write(`phasebook: ${error.message}\n`);
      return error.status;
    }
    const known = error instanceof InputError || error instanceof BlowUpError || error instanceof OutputError;
    const message = known ? error.message : `internal error: ${(error as Error)?.message ?? String(error)}`;
    process.stderr.write(`phasebook: ${message.split('\n')[0]}\n`);
    return 2;
  }
}
