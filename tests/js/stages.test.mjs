// The bench's stage breakdown (bench/stages.mjs) from a page's measures and task clocks.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { stageBreakdown } from '../../bench/stages.mjs';

test('the workers\' table counts the scans\' tasks only, not the Delta matrix\'s nor the reference sets\'', () => {
  const clock = (type, worker, start, end) => ({ type, worker, posted: start - 5, arrived: start - 1, start, read: start + 1, end, received: end + 1 });
  const entries = [
    { name: 'placecat:files', startTime: 0, duration: 0 },
    { name: 'placecat:matrix', startTime: 0, duration: 700 },
    { name: 'placecat:choose', startTime: 990, duration: 120 },
    { name: 'placecat:pool', startTime: 0, duration: 0, detail: [
      clock('describe', 0, 100, 110), clock('describe', 0, 110, 130), clock('describe', 1, 100, 140),
      clock('deltaRows', 0, 200, 900), clock('deltaRows', 1, 200, 880),
      clock('references', 1, 885, 940), clock('references', 0, 905, 960), clock('references', 1, 940, 990),
    ] },
  ];
  const { workers, stages, text } = stageBreakdown(entries, 0);
  assert.deepEqual(workers.map((w) => w.tasks), [2, 1]);
  // Describing: end - read, 9 + 19 ms on worker 0; the matrix's 700 ms are not in it.
  assert.equal(workers[0].describing.toFixed(3), '0.028');
  assert.equal(stages['Delta matrix (in the workers)'], 0.7);
  assert.equal(stages['files to first task'], 0.095);
  // The reference sets: from the first one's start (885) to the last one's end (990).
  assert.equal(stages['reference sets (in the workers, from the first to the last)'], 0.105);
  // The choice's stage under its new key and (output keys are contracts) its first one, the same figure; the table shows it once.
  assert.equal(stages['choose categories (with the wait for the workers\' reference sets)'], 0.12);
  assert.equal(stages['choose categories'], 0.12);
  assert.equal(text.match(/^\| choose categories/gm)?.length, 1);
});
