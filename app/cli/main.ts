/**
 * The `layerbot` command line: the same Session the app drives, headless.
 * Exit codes: 0 ran (a crash is a result), 1 a controller error, 2 bad input or usage.
 */
import { Command, CommanderError, InvalidArgumentError, Option } from 'commander';
import { benchCommand } from './commands/bench';
import { checkCommand } from './commands/check';
import { gradeCommand } from './commands/grade';
import { runCommand } from './commands/run';
import { InputError } from './load';

function integer(name: string, min: number) {
  return (value: string): number => {
    const n = Number(value);
    if (!Number.isInteger(n) || n < min) throw new InvalidArgumentError(`${name} must be a whole number of at least ${min}.`);
    return n;
  };
}

/** Runs the command line with the given arguments; resolves to the exit code. */
export async function main(argv: readonly string[]): Promise<number> {
  let code = 0;
  const out = (s: string) => process.stdout.write(`${s}\n`);
  const err = (s: string) => process.stderr.write(`${s}\n`);
  const program = new Command('layerbot')
    .description('Run, check and grade Layerbot controllers, worlds and challenge packs.')
    .exitOverride()
    .showHelpAfterError();

  program
    .command('run')
    .description('Run a controller in a world, headless, until every plan step is reached, the robot crashes, an error occurs or N ticks pass.')
    .argument('<controller>', 'a *.controller.json file')
    .requiredOption('-w, --world <world>', 'a *.world.json file')
    .option('-t, --ticks <n>', 'the most ticks to run', integer('--ticks', 0), 2000)
    .option('-s, --seed <s>', 'seed every random source (source i gets s + i)', integer('--seed', -(2 ** 53)))
    .option('--trace <file.csv>', 'write the trajectory as CSV: tick,x,y,heading,whisker,crashed')
    .option('--json', 'print a JSON summary: {ticks, crashed, crashTick, goals, error, ticksPerSecond}')
    .addOption(new Option('-e, --engine <engine>', 'the sandbox: the reference interpreter, or the fast engine').choices(['interpreter', 'fast']).default('interpreter'))
    .action(async (controller: string, opts) => {
      code = await runCommand(controller, opts, out);
    });

  program
    .command('check')
    .description('Validate worlds, controllers and challenge packs, and explain every problem.')
    .argument('<files...>', 'files to check')
    .action((files: string[]) => {
      code = checkCommand(files, out, err);
    });

  program
    .command('grade')
    .description('Run every challenge of a pack on each submission and print the verdicts.')
    .argument('<pack>', 'a *.pack.json file')
    .argument('<submissions...>', '*.submission.json files, or *.controller.json files named after a challenge id')
    .option('--csv <file>', 'write one row per submission and challenge')
    .option('--json', 'print JSON: every challenge verdict with passed and its reasons')
    .option('-j, --jobs <n>', 'worker threads (default: one per core; 1 = in-process)', integer('--jobs', 1))
    .option('-s, --seed <s>', 'seed every random source', integer('--seed', -(2 ** 53)))
    .option('--timeout <seconds>', 'the longest one submission may take (default 300)', integer('--timeout', 1))
    .option('--max-steps <n>', "cap on one call's step budget (default 20,000,000)", integer('--max-steps', 1))
    .action(async (pack: string, submissions: string[], opts) => {
      code = await gradeCommand(pack, submissions, opts, out, err);
    });

  program
    .command('bench')
    .description('Measure the performance figures (sandbox vs native, value-iteration replans, ticks per second, history memory, seeking).')
    .option('--json', 'print the figures as JSON')
    .action(async (opts) => {
      code = await benchCommand(opts, out);
    });

  try {
    await program.parseAsync([...argv], { from: 'user' });
    return code;
  } catch (e) {
    if (e instanceof CommanderError) return e.exitCode === 0 ? 0 : 2;
    if (e instanceof InputError) {
      err(e.message);
      return 2;
    }
    err(`layerbot: ${e instanceof Error ? (e.stack ?? e.message) : String(e)}`);
    return 2;
  }
}
