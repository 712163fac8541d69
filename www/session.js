// Results survive a reload: described scans are written to IndexedDB a few
// times a second, in batches (descriptor, summary, preview, pose, label),
// per data set, and the last session is restored on start.
const DB = 'placecat';
const STORE = 'scans';
const META = 'sessions';

function open() {
  return new Promise((resolve, reject) => {
    const req = indexedDB.open(DB, 1);
    req.onupgradeneeded = () => {
      const db = req.result;
      db.createObjectStore(STORE, { keyPath: ['datasetId', 'index'] }).createIndex('datasetId', 'datasetId');
      db.createObjectStore(META, { keyPath: 'key' });
    };
    req.onsuccess = () => resolve(req.result);
    req.onerror = () => reject(req.error);
  });
}

let dbPromise = null;
const db = () => (dbPromise ??= open());

function tx(stores, mode, fn) {
  return db().then((d) => new Promise((resolve, reject) => {
    const t = d.transaction(stores, mode);
    const out = fn(t);
    t.oncomplete = () => resolve(out);
    t.onerror = () => reject(t.error);
    t.onabort = () => reject(t.error);
  }));
}

/** Start a session: forget this data set's old scans, remember it as the last. */
export function beginSession(datasetId, info) {
  return tx([STORE, META], 'readwrite', (t) => {
    const idx = t.objectStore(STORE).index('datasetId');
    idx.openKeyCursor(IDBKeyRange.only(datasetId)).onsuccess = (e) => {
      const c = e.target.result;
      if (c) {
        t.objectStore(STORE).delete(c.primaryKey);
        c.continue();
      }
    };
    t.objectStore(META).put({ key: 'last', datasetId, ...info, started: Date.now() });
  }).catch(() => {});
}

/**
 * Store described scans, [index, scan] each, in one transaction (one put
 * that fails aborts them all): rejects with the error and how many were lost.
 */
export function saveScans(datasetId, scans) {
  return tx([STORE], 'readwrite', (t) => {
    const store = t.objectStore(STORE);
    for (const [index, { name, descriptorJson, summary, preview, site, pose, label, format }] of scans) {
      store.put({ datasetId, index, name, descriptorJson, summary, preview, site, pose, label, format });
    }
    // Commit now, not when the event loop comes back: a batch saved as the page is hidden (a reload) gets written.
    t.commit?.();
  }).catch((e) => {
    throw new Error(`${scans.length} results could not be stored in this browser (${e?.message ?? e}); a reload will not restore them`);
  });
}

/** The last session's data set and its scans in order, or null. */
export async function lastSession() {
  try {
    const meta = await tx([META], 'readonly', (t) => {
      const r = t.objectStore(META).get('last');
      return r;
    });
    const info = meta.result;
    if (!info) return null;
    const scans = await tx([STORE], 'readonly', (t) => t.objectStore(STORE).index('datasetId').getAll(IDBKeyRange.only(info.datasetId)));
    const list = scans.result.sort((a, b) => a.index - b.index);
    return list.length ? { ...info, scans: list } : null;
  } catch {
    return null;
  }
}
