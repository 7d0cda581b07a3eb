/**
 * Builds the JS-Interpreter instance a sandbox runs in: library bugs fixed, non-deterministic
 * built-ins removed, and (once everything is declared) the shared environment locked, so one
 * call cannot leave anything behind for the next: functions stay pure.
 */
import Interpreter from 'js-interpreter';

type Obj = Interpreter.Object;
/** Read once: with bundlers' interop, `Interpreter.Object` may be a getter on every access. */
const PseudoObject = Interpreter.Object;

/**
 * Polyfills run after the library's own (they are appended during construction).
 * - `slice`: the library's throws a RangeError when the end is before the start
 *   (`[3,1,2].slice(2,1)`), which Blockly's sublist block can do.
 * - `sort`: the library's refuses to sort without a comparator.
 * Both stay interpreted, so their work counts against the step budget like any other code.
 */
const POLYFILL_FIXES = `
(function() {
  function toInteger(x) {
    x = Number(x);
    return x !== x ? 0 : (x < 0 ? Math.ceil(x) : Math.floor(x));
  }
  Object.defineProperty(Array.prototype, 'slice', {configurable: true, writable: true, value:
    function slice(start, end) {
      if (this === null || this === undefined) throw TypeError('Array.prototype.slice called on ' + this);
      var o = Object(this), len = o.length >>> 0;
      var k = toInteger(start);
      k = k < 0 ? Math.max(len + k, 0) : Math.min(k, len);
      var last = end === undefined ? len : toInteger(end);
      last = last < 0 ? Math.max(len + last, 0) : Math.min(last, len);
      var out = [];
      for (var i = 0; k < last; k++, i++) {
        if (k in o) out[i] = o[k];
      }
      out.length = i;
      return out;
    }});
  var sort_ = Array.prototype.sort;
  function byText(a, b) {
    if (a === undefined) return b === undefined ? 0 : 1;
    if (b === undefined) return -1;
    a = String(a);
    b = String(b);
    return a < b ? -1 : (a > b ? 1 : 0);
  }
  Object.defineProperty(Array.prototype, 'sort', {configurable: true, writable: true, value:
    function sort(opt_comp) {
      return sort_.call(this, opt_comp === undefined ? byText : opt_comp);
    }});
})();
`;

/** Creates an interpreter with the fixed polyfills and without clocks, timers or randomness. */
export function createInterpreter(): Interpreter {
  const interpreter = new Interpreter('', (it, global) => {
    it.polyfills_?.push(POLYFILL_FIXES);
    removeNondeterminism(it, global);
  });
  // 0: a polyfill (map, join, sort, ...) advances one node per step, so its work is counted and
  // the budget is deterministic; a time slice would make the step count depend on the machine.
  interpreter.POLYFILL_TIMEOUT = 0;
  // Mode 2 runs regular expressions asynchronously (a Worker or Node's vm), which a synchronous
  // step loop cannot wait for; mode 1 runs them natively.
  interpreter.REGEXP_MODE = 1;
  return interpreter;
}

/** Randomness comes from random-source arcs and time from the tick input: replays stay exact. */
function removeNondeterminism(it: Interpreter, global: Obj): void {
  const refuse = (name: string, text: string, isConstructor = false): Obj =>
    it.createNativeFunction(
      Object.defineProperty(
        function (): never {
          it.throwException(it.ERROR, text);
        },
        'name',
        { value: name },
      ),
      isConstructor,
    );
  const math = global.properties['Math'] as Obj;
  it.setProperty(math, 'random', refuse('random', 'Math.random is not available here: use a random input instead (a random source), so that every run can be replayed exactly.'), Interpreter.NONENUMERABLE_DESCRIPTOR);
  const dateText = 'Date is not available here: use the "tick" input to know the time, so that every run can be replayed exactly.';
  const date = refuse('Date', dateText, true);
  it.setProperty(date, 'now', refuse('now', dateText), Interpreter.NONENUMERABLE_DESCRIPTOR);
  it.setProperty(global, 'Date', date, Interpreter.NONENUMERABLE_DESCRIPTOR);
  // Timers would queue tasks that outlive the call.
  for (const name of ['setTimeout', 'setInterval', 'clearTimeout', 'clearInterval']) delete global.properties[name];
}

/**
 * Locks every object reachable from `roots` (the global object, the functions' scopes): built-ins,
 * helpers and the functions themselves become read-only, so no call can change what the next
 * one sees (`Math.floor = ...`, `Array.prototype.push = ...`, reassigning a function's name).
 * Adds each locked object to `locked`, for the write guard's message.
 */
export function lockGraph(roots: readonly Obj[], locked: WeakSet<Obj>): void {
  const todo = [...roots];
  const add = (v: unknown): void => {
    if (v instanceof PseudoObject && !locked.has(v)) todo.push(v);
  };
  for (let o = todo.pop(); o !== undefined; o = todo.pop()) {
    if (locked.has(o)) continue;
    locked.add(o);
    add(o.proto);
    // Descriptors, not reads: an accessor's stored value is a placeholder that throws when read.
    for (const d of Object.values(Object.getOwnPropertyDescriptors(o.properties))) add(d.value);
    for (const k in o.getter) add(o.getter[k]);
    for (const k in o.setter) add(o.setter[k]);
    Object.freeze(o.properties);
    o.preventExtensions = true;
  }
}

/**
 * Routes every write to a non-extensible object through `check`, which throws (inside the
 * interpreter) for inputs and locked built-ins. All writes go through setProperty except
 * `delete`, caught at its step, and `with`, refused; the other direct writes in the library touch
 * only new objects.
 */
export function guardWrites(it: Interpreter, check: (obj: Obj, name: string) => void): void {
  const setProperty = Interpreter.prototype.setProperty;
  const guarded: typeof setProperty = function (this: Interpreter, obj, name, value, descriptor) {
    if (obj instanceof PseudoObject && obj.preventExtensions === true) check(obj, String(name));
    return setProperty.call(this, obj, name, value, descriptor);
  };
  // The library reads its accessor placeholders through `this.setProperty`.
  Object.assign(guarded, setProperty);
  it.setProperty = guarded;
  const unary = it.stepFunctions_['UnaryExpression'];
  it.stepFunctions_['UnaryExpression'] = (stack, state, node) => {
    const ref = state.value;
    if (node['operator'] === 'delete' && state['done_'] === true && Array.isArray(ref)) {
      const target: unknown = ref[0];
      if (target instanceof PseudoObject && target.preventExtensions === true) check(target, String(ref[1]));
    }
    return unary(stack, state, node);
  };
  // `with (input) { x = 1; }` writes to the object's storage directly. Strict code cannot use
  // `with`; refusing it everywhere closes the gap for sources that are not strict.
  it.stepFunctions_['WithStatement'] = () => it.throwException(it.SYNTAX_ERROR, 'The "with" statement is not supported.');
}
