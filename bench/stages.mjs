// The page's stage breakdown from what it records (www/stages.js measures,
// the pool's task clocks of the scans): where a run's wall time goes, for
// `npm run bench`.

/** The choice's stage's first key: the JSON keeps it, the table shows the new one. */
const OLD_CHOOSE = 'choose categories';

/**
 * @param {{name: string, startTime: number, duration: number, detail?: any}[]} entries the page's
 *   `placecat:` marks and measures (performance.getEntries) @param {number} timeOrigin the page's
 * @returns {{stages: Record<string, number>, workers: {tasks: number, reading: number, describing: number, replying: number, waiting: number}[], text: string}}
 *   seconds; between a worker's tasks, `replying`: posting its result (and anything else before the next task
 *   starts), `waiting`: for the next task to come
 */
export function stageBreakdown(entries, timeOrigin) {
  const sum = (name) => entries.filter((e) => e.name === `placecat:${name}`).reduce((s, e) => s + e.duration, 0) / 1000;
  const files = entries.find((e) => e.name === 'placecat:files');
  const run = entries.find((e) => e.name === 'placecat:run');
  // The scans' tasks: the Delta matrix's (deltaRows) have their own stage above.
  const clocks = /** @type {any[]} */ (entries.find((e) => e.name === 'placecat:pool')?.detail ?? []).filter((c) => c.type === 'describe');
  const firstPosted = Math.min(...clocks.map((c) => c.posted)) - timeOrigin;
  const byStart = [...clocks].sort((a, b) => a.posted - b.posted);
  const stages = {
    'files to first task': files ? (firstPosted - files.startTime) / 1000 : NaN,
    'first scan alone (preset)': byStart.length > 1 ? (byStart[1].posted - byStart[0].posted) / 1000 : NaN,
    'describe (all scans)': sum('describe'),
    'load descriptors': sum('load'),
    'Delta matrix (in the workers)': sum('matrix'),
    'tree (and the Delta matrix, if not given)': sum('tree'),
    // The same figure under the key it had before the reference sets moved to the workers (output keys are kept): not in the table.
    [OLD_CHOOSE]: sum('choose'),
    'choose categories (with the wait for the workers\' reference sets)': sum('choose'),
    'cut and medoids': sum('cut') + sum('medoids'),
    'draw': sum('draw'),
    'run (from the first task)': run ? run.duration / 1000 : NaN,
  };
  // The choice's reference sets, in the workers beside the tree (matrix.js): from the first one's start to the last one's end.
  const sets = /** @type {any[]} */ (entries.find((e) => e.name === 'placecat:pool')?.detail ?? []).filter((c) => c.type === 'references');
  stages['reference sets (in the workers, from the first to the last)'] = sets.length ? (Math.max(...sets.map((c) => c.end)) - Math.min(...sets.map((c) => c.start))) / 1000 : 0;
  const workers = [];
  for (const w of new Set(clocks.map((c) => c.worker))) {
    const mine = clocks.filter((c) => c.worker === w).sort((a, b) => a.start - b.start);
    let waiting = 0, replying = 0;
    for (let k = 1; k < mine.length; k++) {
      const gap = Math.max(0, mine[k].start - mine[k - 1].end);
      const late = Math.min(gap, Math.max(0, mine[k].arrived - mine[k - 1].end));
      waiting += late;
      replying += gap - late;
    }
    workers.push({
      tasks: mine.length,
      reading: mine.reduce((s, c) => s + (c.read ? Math.max(0, c.read - c.start) : 0), 0) / 1000,
      describing: mine.reduce((s, c) => s + (c.end - Math.max(c.read, c.start)), 0) / 1000,
      waiting: waiting / 1000,
      replying: replying / 1000,
    });
  }
  const lines = Object.entries(stages).filter(([k]) => k !== OLD_CHOOSE).map(([k, v]) => `| ${k} | ${v.toFixed(2)} |`);
  const wl = workers.map((w, i) => `| worker ${i} | ${w.tasks} | ${w.reading.toFixed(2)} | ${w.describing.toFixed(2)} | ${w.replying.toFixed(2)} | ${w.waiting.toFixed(2)} |`);
  const text = ['| stage (main thread) | s |', '|---|---|', ...lines, '',
    '| worker | tasks | waiting for the file\'s bytes (s) | describing (s) | replying (s) | waiting for the next task (s) |', '|---|---|---|---|---|---|', ...wl].join('\n');
  return { stages, workers, text };
}
