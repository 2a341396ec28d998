#!/usr/bin/env node
// The CLI is TypeScript shared with the widgets; tsx compiles it on load.
import { register } from 'tsx/esm/api';

register();
const { main } = await import('../widgets/cli/main.ts');
process.exitCode = await main(process.argv.slice(2));
