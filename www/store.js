// What must survive a reload: the user's names for categories, keyed by
// data set. Names are anchored to scans (a category takes the name anchored
// to its most central scan), so they survive re-clustering.
const KEY = (id) => `placecat:names:${id}`;

export function loadNames(datasetId) {
  try {
    const v = JSON.parse(localStorage.getItem(KEY(datasetId)) || '{}');
    return v && typeof v === 'object' && !Array.isArray(v) ? v : {};
  } catch {
    return {};
  }
}

export function saveNames(datasetId, anchors) {
  try {
    localStorage.setItem(KEY(datasetId), JSON.stringify(anchors));
    return true;
  } catch {
    return false; // storage full or disabled: the names stay in the page
  }
}

/** A short stable id for a list of file names. */
export function datasetId(names) {
  let h = 2166136261;
  for (const n of names) {
    for (let i = 0; i < n.length; i++) h = Math.imul(h ^ n.charCodeAt(i), 16777619);
    h = Math.imul(h ^ 10, 16777619);
  }
  return `files-${names.length}-${(h >>> 0).toString(16)}`;
}
