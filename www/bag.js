// ROS bags in the page (the worker's side is bagreader.js). A bag is one
// input that yields many scans. Before a run each bag's topics are listed
// (in a worker, from the bag's index or summary) to choose the cloud topic
// (the only PointCloud2 topic, else the user picks one) and the thinning;
// after the run the page says what was kept of each bag.
import { $ } from './view.js';
import { isBag } from './files.js';

/**
 * A bag input's reading: the cloud topic (none: the only one), whether the
 * bag has poses (odometry or tf), and the thinning with its wording.
 * @typedef {{topic?: string, hasPoses: boolean, every?: number, everyMetres?: number, thinning: string}} BagChoice
 */
/** @typedef {{name: string, file?: File, bag?: BagChoice}} BagInput */
/** What the worker says of a recording at the end (bagreader.js; `topic`: a bag's).
 * @typedef {{recording: true, topic?: string, kept: number, failed: number, total: number}} BagInfo */

/** sensor_msgs/PointCloud2 as ROS 1 and rosbag2 spell it. @param {string} type */
export const isCloudType = (type) => /^sensor_msgs\/(msg\/)?PointCloud2$/.test(type);
/** @param {string} type */
const isOdometry = (type) => /^nav_msgs\/(msg\/)?Odometry$/.test(type);
/** @param {string} type */
const isTf = (type) => /^tf2_msgs\/(msg\/)?TFMessage$/.test(type);
/** The types the bag reader takes poses from. @param {string} type */
export const isPoseType = (type) => isOdometry(type) || isTf(type);

/**
 * Whether the bag reader finds poses by itself, as it chooses them
 * (src/io/bag/reader.rs, choose_poses): the only odometry topic, else tf.
 * @param {{type: string}[]} topics
 */
export const hasPoses = (topics) => topics.filter((t) => isOdometry(t.type)).length === 1 || topics.some((t) => isTf(t.type));

/**
 * The page's default thinning, with poses: one cloud a metre. A robot
 * records ~10 clouds a second; at walking pace (1-1.5 m/s) that is a cloud
 * every 10-15 cm, near-duplicates of each other. A metre apart, the clouds
 * still sample each room several times over, and a bag of a building walk
 * gives hundreds of scans, not tens of thousands. Without poses, every cloud.
 */
export const DEFAULT_METRES = 1;

/**
 * The thinning the form asks for, for a bag with or without poses.
 * @param {'auto' | 'metres' | 'every'} mode @param {number} step @param {boolean} hasPoses
 * @returns {{every?: number, everyMetres?: number, thinning: string}}
 */
export function thinningOf(mode, step, hasPoses) {
  if (mode === 'auto') return hasPoses ? metres(DEFAULT_METRES) : { every: 1, thinning: 'every cloud (the bag has no poses)' };
  if (mode === 'metres') {
    const d = step > 0 && Number.isFinite(step) ? step : DEFAULT_METRES;
    return hasPoses ? metres(d) : { every: 1, thinning: `every cloud (no poses to measure ${d} m by)` };
  }
  const n = Math.max(1, Math.round(step) || 1);
  return { every: n, thinning: n === 1 ? 'every cloud' : `every ${ordinal(n)} cloud` };
}

/** @param {number} d */
const metres = (d) => ({ everyMetres: d, thinning: `one cloud every ${d} m along the path` });

/** 2 -> 2nd, 3 -> 3rd, 11 -> 11th. @param {number} n */
function ordinal(n) {
  const tens = Math.floor(n / 10) % 10;
  const suffix = tens !== 1 && ['th', 'st', 'nd', 'rd'][n % 10] || 'th';
  return `${n}${suffix}`;
}

/** Call `fn` when the user changes the thinning. @param {() => void} fn */
export function onThinning(fn) {
  for (const id of ['bag-thin', 'bag-step']) $(id).addEventListener('change', fn);
}

/** The thinning form's values. */
function thinningForm() {
  const mode = /** @type {'auto' | 'metres' | 'every'} */ ($('bag-thin').value);
  return { mode, step: Number($('bag-step').value) };
}

/** Counts the calls of chooseBagReading: files dropped again supersede a question not yet answered. */
let generation = 0;
/** @type {AbortController | null} the pending question's */
let asking = null;

/**
 * The inputs with each bag's reading chosen: its topics listed in a worker,
 * the user asked for the cloud topic when there are several, the thinning
 * from the form. A bag whose topics cannot be listed keeps the defaults:
 * its run then fails with the message naming it. Null when files were
 * dropped again before the user chose a topic (the newer drop goes on).
 * @template {BagInput} I @param {import('./pool.js').WorkerPool} pool @param {I[]} inputs @returns {Promise<I[] | null>}
 */
export async function chooseBagReading(pool, inputs) {
  const mine = ++generation;
  asking?.abort();
  const { mode, step } = thinningForm();
  const out = [];
  for (const input of inputs) {
    if (!isBag(input.name)) {
      out.push(input);
      continue;
    }
    /** @type {{name: string, type: string, count: number}[]} */
    let topics = [];
    try {
      topics = await pool.run({ type: 'bagTopics', file: input.file, name: input.name });
    } catch { /* the bag's run says why */ }
    if (mine !== generation) return null;
    const clouds = topics.filter((t) => isCloudType(t.type));
    const posed = hasPoses(topics);
    const topic = clouds.length > 1 ? await askTopic(input.name, clouds) : undefined;
    if (mine !== generation) return null;
    out.push({ ...input, bag: { topic, hasPoses: posed, ...thinningOf(mode, step, posed) } });
  }
  showBags(out);
  return out;
}

/** The inputs with the form's new thinning (same topics). @template {BagInput} I @param {I[]} inputs @returns {I[]} */
export function rethinned(inputs) {
  const { mode, step } = thinningForm();
  return inputs.map((i) => (i.bag ? { ...i, bag: { topic: i.bag.topic, hasPoses: i.bag.hasPoses, ...thinningOf(mode, step, i.bag.hasPoses) } } : i));
}

/**
 * Ask which PointCloud2 topic of the bag to read, listing them.
 * @param {string} name @param {{name: string, count: number}[]} clouds @returns {Promise<string | undefined>} undefined when superseded
 */
function askTopic(name, clouds) {
  const box = $('bag-topic-box');
  const select = /** @type {HTMLSelectElement} */ (/** @type {unknown} */ ($('bag-topic')));
  $('bag-topic-file').textContent = `${name} has ${clouds.length} PointCloud2 topics; read which?`;
  select.replaceChildren(...clouds.map((c) => new Option(`${c.name} (${c.count} clouds)`, c.name)));
  box.hidden = false;
  select.focus();
  const ask = (asking = new AbortController());
  return new Promise((resolve) => {
    const done = (/** @type {string | undefined} */ topic) => {
      box.hidden = true;
      resolve(topic); // before the abort, whose listener comes back here with undefined
      ask.abort();
    };
    $('bag-topic-read').addEventListener('click', () => done(select.value), { signal: ask.signal });
    ask.signal.addEventListener('abort', () => done(undefined));
  });
}

/**
 * Say how each bag is read and, after the run, what was kept of it (and of
 * an E57 survey, what was described: only recordings have infos).
 * @param {BagInput[]} inputs @param {(BagInfo | undefined)[]} [infos] by input
 */
export function showBags(inputs, infos) {
  const after = infos !== undefined;
  infos ??= [];
  const lines = inputs.flatMap((input, i) => {
    const info = infos[i];
    if (!input.bag) {
      const failed = info?.failed ? `, ${info.failed} could not be read or described` : '';
      return info ? [`${input.name}: ${info.kept} of ${info.total} scans described${failed}`] : [];
    }
    if (after && !info) return [`${input.name}: not read (see the skipped files)`];
    const topic = info?.topic ?? input.bag.topic ?? 'its PointCloud2 topic';
    const kept = info ? `: ${info.kept} of ${info.total} clouds kept` : '';
    const failed = info?.failed ? `, ${info.failed} could not be read` : '';
    return [`${input.name}, ${topic}${kept}${failed} (${input.bag.thinning})`];
  });
  $('bag-note').textContent = lines.join('\n');
}
