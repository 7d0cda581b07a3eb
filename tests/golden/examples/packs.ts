/**
 * Keeps the sample pack's value-iteration controllers in step with the example: every controller
 * in examples/packs/ with a "Value iteration" layer (a starter or a reference solution) gets the
 * example's layers; a starter keeps its own CELL_SIZE, since tuning it is the challenge.
 */
import type { ControllerSpec } from '../../../app/core/controller/model';
import { serializeController } from '../../../app/core/formats';

type Json = Record<string, unknown>;
interface FileLayer extends Json {
  name: string;
  variables: { name: string; value: unknown }[];
}
interface FileController extends Json {
  layers: FileLayer[];
}

const VI_LAYER = 'Value iteration';

const isValueIteration = (c: FileController) => c.layers.some((l) => l.name === VI_LAYER);

function cellSize(c: FileController): unknown {
  return c.layers.find((l) => l.name === VI_LAYER)?.variables.find((v) => v.name === 'CELL_SIZE')?.value;
}

/** The example's layers as a controller file holds them, with CELL_SIZE set when given. */
function exampleLayers(example: ControllerSpec, cell?: unknown): FileLayer[] {
  const layers = (JSON.parse(serializeController(example)) as FileController).layers;
  if (cell === undefined) return layers;
  return layers.map((l) => ({ ...l, variables: l.variables.map((v) => (v.name === 'CELL_SIZE' ? { ...v, value: cell } : v)) }));
}

/** The pack with its value-iteration starters rebuilt from the example (each keeping its CELL_SIZE). */
export function packWithExample(pack: Json, example: ControllerSpec): Json {
  const challenges = (pack.challenges as Json[]).map((c) => {
    const starter = c.starter as FileController;
    return isValueIteration(starter) ? { ...c, starter: { ...starter, layers: exampleLayers(example, cellSize(starter)) } } : c;
  });
  return { ...pack, challenges };
}

/** The submission with its value-iteration controllers replaced by the example's layers. */
export function submissionWithExample(submission: Json, example: ControllerSpec): Json {
  const controllers = Object.fromEntries(
    Object.entries(submission.controllers as Record<string, FileController>).map(([id, c]) => [id, isValueIteration(c) ? { ...c, layers: exampleLayers(example) } : c]),
  );
  return { ...submission, controllers };
}
