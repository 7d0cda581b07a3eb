/** Names the fast engine's generated code relies on, shared by the instrumenter and the compartment. */
import { API, SPECIAL_NAMES } from './api';

/** Names the engine's own bindings start with; student code may not use them. */
export const RESERVED_PREFIX = '$lb$';

/** ES5's global names, as JS-Interpreter provides them (`eval` aside: strict code cannot bind it). */
export const ES5_GLOBALS = [
  'Infinity', 'NaN', 'undefined', 'isFinite', 'isNaN', 'parseFloat', 'parseInt', 'decodeURI', 'decodeURIComponent', 'encodeURI',
  'encodeURIComponent', 'escape', 'unescape', 'Array', 'Boolean', 'Number', 'Object', 'String', 'Error', 'EvalError', 'RangeError',
  'ReferenceError', 'SyntaxError', 'TypeError', 'URIError', 'RegExp', 'JSON', 'Math', 'Date', 'Function',
] as const;

/** `print`, `__block` and the API helpers: bound as locals of the declaring closure. */
export const NATIVE_NAMES: readonly string[] = [...Object.keys(API), ...SPECIAL_NAMES];

/** Every name a function may use without declaring it (`eval` is renamed to a bound thrower). */
export const BOUND_NAMES: ReadonlySet<string> = new Set<string>([...ES5_GLOBALS, ...NATIVE_NAMES, 'eval']);
