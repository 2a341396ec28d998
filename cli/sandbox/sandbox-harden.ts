/**
 * What the sandbox takes away from its own global scope before any user
 * code is compiled: defence in depth behind Node's permission model
 * (sandbox-flags.ts), which does not cover everything on every version of
 * Node (the network before Node 25, signals to other processes on any).
 *
 * The `process` object goes altogether: with it go `process.kill`,
 * `process.getBuiltinModule` (every Node module, the network's included,
 * without an import), `process.binding`, `process.dlopen`, `process.env`,
 * `process.exit` and the IPC channel's `process.send`. The sandbox keeps what
 * it needs of them here, bound, before they go. So do the globals that reach
 * the network (fetch, WebSocket, EventSource). With code from strings
 * disallowed and the user's code compiled without a dynamic import() hook
 * (js-source.ts), that code has nothing left that names a Node module.
 *
 * This is not the boundary: a way around it would be a global this list
 * missed. The boundary is the permission model.
 */
import type { SandboxReply, SandboxRequest } from './sandbox-messages.ts';

/** The sandbox's line to the CLI, kept from `process` before it is taken away. */
export interface Channel {
  send(reply: SandboxReply): void;
  /** the CLI's requests, one at a time */
  onRequest(listener: (request: SandboxRequest) => void): void;
  /** the CLI is gone: so is the reason to run */
  onDisconnect(listener: () => void): void;
  exit(code: number): void;
}

/** Globals through which code reaches the network without naming a module. */
const NETWORK_GLOBALS = ['fetch', 'WebSocket', 'EventSource', 'XMLHttpRequest'];

/** Keeps the channel to the CLI, then removes `process` and the network's globals from the global scope. */
export function harden(): Channel {
  const own = process;
  if (typeof own.send !== 'function') throw new Error('the sandbox was started without its channel to the CLI');
  const send = own.send.bind(own);
  const on = own.on.bind(own);
  const exit = own.exit.bind(own);
  const global = globalThis as Record<string, unknown>;
  for (const name of NETWORK_GLOBALS) delete global[name];
  // Its environment is empty already (sandbox-process.ts); emptied again here in case a version of Node adds to it.
  for (const key of Object.keys(own.env)) delete own.env[key];
  delete global.process;
  if ('process' in globalThis) throw new Error('the sandbox could not take process out of its global scope');
  return {
    send: (reply) => void send(reply),
    onRequest: (listener) => void on('message', listener),
    onDisconnect: (listener) => void on('disconnect', listener),
    exit: (code) => exit(code),
  };
}
