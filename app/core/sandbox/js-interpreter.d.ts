/**
 * Typings for the parts of `js-interpreter` 6.0.2 the sandbox uses (the package ships none).
 * Several members are internal to the library (trailing underscore, the state stack, the step
 * functions): the version is pinned and tests/unit/sandbox guards the behaviour relied on.
 */
declare module 'js-interpreter' {
  namespace Interpreter {
    /** A value inside the interpreter: a primitive or a pseudo object. */
    type Value = Object | boolean | number | string | null | undefined;

    /** An Acorn AST node (only the fields the sandbox reads or builds). */
    interface Node {
      type: string;
      start?: number;
      end?: number;
      body?: Node | Node[];
      id?: { name: string } | null;
      [field: string]: unknown;
    }

    interface Descriptor {
      configurable?: boolean;
      enumerable?: boolean;
      writable?: boolean;
      value?: Value;
    }

    /** An object inside the interpreter. */
    class Object {
      constructor(proto: Object | null);
      proto: Object | null;
      /** 'Object', 'Array', 'Function', 'Error', 'RegExp', 'Date', 'Number', ... */
      class: string;
      properties: Record<string, Value>;
      getter: Record<string, unknown>;
      setter: Record<string, unknown>;
      data: unknown;
      /** Set by Object.preventExtensions (and by the sandbox on inputs and built-ins). */
      preventExtensions?: boolean;
      /** Interpreted functions: their declaration node and defining scope. */
      node?: Node;
      parentScope?: Scope;
    }

    class Scope {
      constructor(parentScope: Scope | null, strict: boolean, object: Object);
      parentScope: Scope | null;
      strict: boolean;
      object: Object;
    }

    /** One frame of the interpreter's state stack; step functions add their own fields. */
    class State {
      constructor(node: Node, scope: Scope);
      node: Node;
      scope: Scope;
      value: unknown;
      done?: boolean;
      [field: string]: unknown;
    }

    type StepFunction = (stack: State[], state: State, node: Node) => State | undefined;

    const NONENUMERABLE_DESCRIPTOR: Descriptor;
    const READONLY_NONENUMERABLE_DESCRIPTOR: Descriptor;
    /** Thrown internally by throwException; never escapes `step()`. */
    const STEP_ERROR: unknown;
    /** Cycle guard of Array/Error toString, shared by all interpreters. */
    const toStringCycles_: unknown[];
  }

  class Interpreter {
    constructor(code: string | Interpreter.Node, initFunc?: (interpreter: Interpreter, globalObject: Interpreter.Object) => void);
    REGEXP_MODE: 0 | 1 | 2;
    POLYFILL_TIMEOUT: number;
    stateStack: Interpreter.State[];
    value: unknown;
    paused_: boolean;
    getterStep_: boolean;
    setterStep_: boolean;
    /** Polyfill sources, run once at the end of construction (undefined afterwards). */
    polyfills_: string[] | undefined;
    stepFunctions_: Record<string, Interpreter.StepFunction>;
    globalScope: Interpreter.Scope;
    globalObject: Interpreter.Object;
    OBJECT_PROTO: Interpreter.Object;
    ARRAY_PROTO: Interpreter.Object;
    ERROR: Interpreter.Object;
    TYPE_ERROR: Interpreter.Object;
    RANGE_ERROR: Interpreter.Object;
    SYNTAX_ERROR: Interpreter.Object;
    step(): boolean;
    parse_(code: string, sourceFile: string): Interpreter.Node;
    createScope(node: Interpreter.Node, parentScope: Interpreter.Scope | null): Interpreter.Scope;
    createNativeFunction(fn: (this: Interpreter.Value, ...args: Interpreter.Value[]) => Interpreter.Value, isConstructor: boolean): Interpreter.Object;
    setProperty(obj: Interpreter.Value, name: Interpreter.Value, value: Interpreter.Value, descriptor?: Interpreter.Descriptor): Interpreter.Object | undefined;
    throwException(errorClass: Interpreter.Object, message?: string): never;
  }

  export = Interpreter;
}
