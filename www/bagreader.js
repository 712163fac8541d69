// The worker's side of a recording, a ROS bag (bag.js is the page's side)
// or an E57 survey: the file is read in slices of its File (FileReaderSync
// over File.slice), never whole, and each kept cloud or station is
// described and posted as it comes, so progress moves and memory holds one
// scan (and one chunk of the bag) at a time. Like engine.js, every wasm
// object made here is freed here.
import { scanResult, scoped } from './engine.js';
import { rangeShare, suggestPreset } from './suggest.js';

/** @typedef {typeof import('./pkg/placecat.js')} Wasm */
/** @typedef {import('./engine.js').Params} Params */
/** @typedef {import('./engine.js').ScanResult} ScanResult */
/**
 * A bag to describe: the cloud topic (none: the bag's only one), and the
 * thinning: every Nth cloud, or one every so many metres along the path.
 * @typedef {{file: File, name: string, topic?: string, every?: number, everyMetres?: number,
 *   params: Params, byPreset?: Record<import('./suggest.js').SuggestedPreset, Params>, previewPoints?: number}} BagTask
 */
/** An E57 survey to describe: every station, in file order.
 * @typedef {{file: File, name: string, params: Params, byPreset?: Record<import('./suggest.js').SuggestedPreset, Params>, previewPoints?: number}} SurveyTask */
/** The wasm reader of a recording: BagClouds or E57Scans (`topic`: a bag's).
 * @typedef {{next(): import('./pkg/placecat.js').DescribedScan | undefined, met: number, total: number, topic?: string, free(): void}} Recording */
/** A partial reply: a described cloud or one that failed, and how far the reading is.
 * @typedef {{scan?: ScanResult, error?: string, met: number, total: number}} BagPartial */

/**
 * `read(offset, length)` over a File, as BagClouds and bagTopics take it.
 * @param {File} file
 */
export function sliceReader(file) {
  // Workers only (the page's type check knows the DOM, not the worker's globals).
  const reader = new (/** @type {any} */ (self).FileReaderSync)();
  return (/** @type {number} */ offset, /** @type {number} */ length) => reader.readAsArrayBuffer(file.slice(offset, offset + length));
}

/** The bag's topics (only its index or summary is read). @param {Wasm} wasm @param {File} file @param {string} name */
export function bagTopics(wasm, file, name) {
  return wasm.bagTopics(file.size, sliceReader(file), name);
}

/** Describe a bag's kept clouds (describeRecording). @param {Wasm} wasm @param {BagTask} t @param {(p: BagPartial, transfer: Transferable[]) => void} post */
export function describeBag(wasm, t, post) {
  const open = (/** @type {Params} */ params) =>
    new wasm.BagClouds(t.file.size, sliceReader(t.file), t.name, t.topic, t.every, params, undefined, t.previewPoints ?? 3000, t.everyMetres);
  return describeRecording(open, t, post);
}

/** Describe every station of an E57 survey (describeRecording). @param {Wasm} wasm @param {SurveyTask} t @param {(p: BagPartial, transfer: Transferable[]) => void} post */
export function describeSurvey(wasm, t, post) {
  const open = (/** @type {Params} */ params) => new wasm.E57Scans(t.file.size, sliceReader(t.file), t.name, params, undefined, t.previewPoints ?? 3000);
  return describeRecording(open, t, post);
}

/** A described cloud as plain data. @param {import('./pkg/placecat.js').DescribedScan} scan @returns {ScanResult} */
function resultOf(scan) {
  return { ...scanResult(scan), pose: scan.pose() ?? undefined };
}

/** The next scan, undefined after the last; throws for one that cannot be read. @param {Recording} clouds */
const nextOf = (clouds) => {
  const scan = clouds.next();
  return scan ? scoped(scan, resultOf) : undefined;
};

/**
 * Describe the scans of a recording (a bag's kept clouds, a survey's
 * stations), posting each (or its error) as a partial reply. With
 * `byPreset` (the first input of a new data set), the first scan read
 * decides the preset by its share of far points (its preview's), as a file
 * does (describe.js); when that is not indoor the recording is opened again
 * with the chosen preset and its scans read again from the first, whose
 * errors are not posted twice. Returns what the page shows of it. One that
 * cannot be opened throws (its message names the file).
 * @param {(params: Params) => Recording} open
 * @param {{params: Params, byPreset?: Record<import('./suggest.js').SuggestedPreset, Params>}} t
 * @param {(p: BagPartial, transfer: Transferable[]) => void} post
 */
function describeRecording(open, t, post) {
  let clouds = open(t.byPreset?.indoor ?? t.params);
  /** @type {{preset?: import('./suggest.js').SuggestedPreset, far?: number}} */
  const chosen = {};
  let kept = 0, failed = 0, tries = 0;
  try {
    const progress = () => ({ met: clouds.met, total: clouds.total });
    /** The next cloud ({scan: undefined} at the end), or null for a bad one, posted and skipped. */
    const readNext = () => {
      try {
        return { scan: nextOf(clouds) };
      } catch (e) {
        // The reader goes on after a bad cloud; this only guards against one that would not.
        if (++failed > clouds.total + 100) throw e;
        post({ error: String(/** @type {any} */ (e)?.message ?? e), ...progress() }, []);
        return null;
      }
    };
    for (;;) {
      const first = readNext();
      if (!first) continue;
      let scan = first.scan;
      tries++;
      if (!scan) break;
      if (t.byPreset && chosen.preset === undefined) {
        chosen.far = rangeShare(scan.preview).far;
        chosen.preset = suggestPreset(chosen.far);
        if (chosen.preset !== 'indoor') {
          clouds.free();
          clouds = open(t.byPreset[chosen.preset]);
          // Read again up to this cloud; the errors before it were posted.
          for (let skip = failed + tries - 1; skip > 0; skip--) {
            try { clouds.next()?.free(); } catch { /* posted on the first pass */ }
          }
          // This cloud read again under the new preset: one that fails now is
          // posted and skipped like any bad cloud, not the end of the bag.
          const again = readNext();
          if (!again) continue;
          scan = again.scan;
          if (!scan) break;
        }
      }
      kept++;
      post({ scan, ...progress() }, [scan.preview.buffer, ...(scan.site ? [scan.site.buffer] : [])]);
    }
    return { recording: true, topic: clouds.topic, kept, failed, total: clouds.total, ...chosen };
  } finally {
    clouds.free();
  }
}
