// Importing names: a categories CSV names the categories by their members'
// names; a model JSON is loaded (for classifying new scans) and names the
// unnamed categories after its own.
import * as S from './state.js';

/**
 * The state with the imported names, and what to tell the user. Throws on
 * anything malformed, and then the state (and the engine's model) stay.
 * @param {S.State} s @param {import('./engine.js').Engine} engine @param {string} fileName @param {string} text
 * @returns {{state: S.State, said: string}}
 */
export function importNames(s, engine, fileName, text) {
  if (fileName.toLowerCase().endsWith('.csv')) return { state: S.withNamesCsv(s, text), said: `Names imported from ${fileName}.` };
  const categories = engine.loadModel(text); // throws on anything malformed
  // Name current categories after the model's, where unnamed; but a model
  // of other parameters would name them by descriptors it cannot compare
  // (new scans it describes itself, with its own).
  const unnamed = S.unnamed(s);
  const refusal = unnamed.length && s.params ? engine.paramsRefusal(s.params) : null;
  const names = refusal ? [] : unnamed.map(([i, json]) => /** @type {[number, string]} */ ([i, engine.classifyJson(json).name]));
  const kept = refusal ? ` The categories here keep their names: this run's scans were described with other parameters (${refusal}).` : '';
  return {
    state: S.withNames(S.withModel(s, text), new Map(names)),
    said: `Model loaded from ${fileName}: ${categories.map((c) => c.name).join(', ')}. New scans can be classified.${kept}`,
  };
}
