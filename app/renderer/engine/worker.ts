/**
 * The engine Worker: runs the Session off the page's thread so the page keeps drawing while the
 * robot runs, and a Stop is read between slices of ticks. Blockly is not loaded here: the page
 * sends the generated code with the controller (see bodies.ts).
 *
 * Ticks run in the fast engine (SES) when it can start here, else in JS-Interpreter (engines.ts).
 * The Worker's name asks for JS-Interpreter when it ends in "-interpreter".
 */
/// <reference lib="webworker" />
import { chooseEngine } from './engines';
import { EngineHost } from './host';
import type { EngineCommand, EngineEvent } from './protocol';
import { isEngineCommand } from './validate';

const scope = self as unknown as DedicatedWorkerGlobalScope;

// A MessageChannel yields to the Worker's message queue without setTimeout's 4 ms clamp.
const channel = new MessageChannel();
const queued: (() => void)[] = [];
channel.port1.onmessage = () => queued.shift()?.();
const later = (fn: () => void, ms: number): void => {
  if (ms > 1) setTimeout(fn, ms);
  else {
    queued.push(fn);
    channel.port2.postMessage(null);
  }
};

const engine = chooseEngine(scope.name.endsWith('-interpreter') ? 'interpreter' : 'fast');
scope.postMessage({ type: 'engine', engine: engine.name, note: engine.note } satisfies EngineEvent);

const host = new EngineHost(
  engine.sandbox,
  (event: EngineEvent) => scope.postMessage(event),
  () => performance.now(),
  later,
);

scope.onmessage = (e: MessageEvent<unknown>) => {
  if (!isEngineCommand(e.data)) {
    scope.postMessage({ type: 'problem', message: 'The engine received a message it does not understand.' } satisfies EngineEvent);
    return;
  }
  try {
    host.handle(e.data as EngineCommand);
  } catch (err) {
    scope.postMessage({ type: 'problem', message: err instanceof Error ? err.message : String(err) } satisfies EngineEvent);
  }
};
