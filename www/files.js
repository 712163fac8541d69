// Collecting files from inputs and drag-and-drop (folders included).

/** A ROS bag (ROS 1 .bag, rosbag2 .mcap): one input that yields many scans (bag.js).
 * rosbag2's SQLite storage (.db3) counts too, to be refused with the core's message when the worker opens it. */
export const isBag = (name) => /\.(bag|mcap|db3)$/i.test(name);
/** A file of one scan the wasm reader takes (src/io: PLY, PCD, KITTI .bin, LAS/LAZ, single-scan E57), or a bag. */
export const isScan = (name) => /\.(ply|pcd|bin|las|laz|e57)$/i.test(name) || isBag(name);
/** An E57 file: a survey of one or more scans (bagreader.js). */
export const isSurvey = (name) => /\.e57$/i.test(name);
export const isTruth = (name) => /(^|\/)labels\.csv$/i.test(name);
export const isPoses = (name) => /poses[^/]*\.(txt|csv)$/i.test(name) || /(^|\/)(trajectory|groundtruth)[^/]*\.(txt|csv)$/i.test(name);

/** Every File under a drop, walking directories (readEntries gives at most 100 a call). */
export async function filesFromDrop(dataTransfer) {
  const entries = [...dataTransfer.items].map((it) => it.webkitGetAsEntry?.()).filter(Boolean);
  if (entries.length === 0) return [...dataTransfer.files];
  const out = [];
  const walk = async (entry, path) => {
    if (entry.isFile) {
      const file = await new Promise((res, rej) => entry.file(res, rej));
      out.push({ file, name: path + file.name });
    } else if (entry.isDirectory) {
      const reader = entry.createReader();
      for (;;) {
        const batch = await new Promise((res, rej) => reader.readEntries(res, rej));
        if (batch.length === 0) break;
        for (const e of batch) await walk(e, `${path}${entry.name}/`);
      }
    }
  };
  for (const e of entries) await walk(e, '');
  return out;
}

/**
 * Files by kind: scans (in natural name order), labels.csv files, poses
 * files and the rest. @template {{name: string}} F @param {F[]} list
 */
export function sortFiles(list) {
  const scans = list.filter((f) => isScan(f.name)).sort((a, b) => a.name.localeCompare(b.name, undefined, { numeric: true }));
  const truth = list.filter((f) => !isScan(f.name) && isTruth(f.name));
  const poses = list.filter((f) => !isScan(f.name) && !isTruth(f.name) && isPoses(f.name));
  const other = list.filter((f) => !isScan(f.name) && !isTruth(f.name) && !isPoses(f.name));
  return { scans, truth, poses, other };
}

/** Make `el` take dropped files and folders, handing them to `onFiles`.
 * @param {HTMLElement} el @param {(files: {file: File, name: string}[]) => void} onFiles */
export function dropZone(el, onFiles) {
  el.addEventListener('dragover', (e) => {
    e.preventDefault();
    el.classList.add('over');
  });
  el.addEventListener('dragleave', () => el.classList.remove('over'));
  el.addEventListener('drop', async (e) => {
    e.preventDefault();
    el.classList.remove('over');
    if (e.dataTransfer) onFiles(await filesFromDrop(e.dataTransfer));
  });
}

/** Normalise a FileList (from an input) to [{file, name}]. */
export function filesFromInput(list) {
  return [...list].map((file) => ({ file, name: file.webkitRelativePath || file.name }));
}

/**
 * A file's name without its folders. A bag cloud's name
 * (`run.bag:/points:000012`, bag.js) keeps its topic, whose slashes are no
 * folders: only the folders before the bag go.
 * @param {string} name
 */
export function baseName(name) {
  // A recording's scans keep their suffix whole (a topic, a station named "Level 1/Scan 3").
  const bag = /\.(bag|mcap|e57):/i.exec(name);
  const end = bag ? bag.index : name.length;
  return name.slice(name.lastIndexOf('/', end) + 1);
}
