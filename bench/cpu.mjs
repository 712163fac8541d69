// CPU seconds used by the threads of the Chromium the bench launched (Linux
// /proc), by process type and thread name: what a run of the page costs the
// machine, whatever else runs on it (wall time on a shared machine says
// little; CPU / cores is a floor). Only the launched browser's process tree
// counts: other Chromiums on the machine (another session's tests) do not.
import { readFileSync, readdirSync } from 'node:fs';

/** The parent pid of each process now running. @returns {Map<number, number>} */
function parents() {
  const out = new Map();
  for (const d of readdirSync('/proc').filter((x) => /^\d+$/.test(x))) {
    try {
      const st = readFileSync(`/proc/${d}/stat`, 'utf8');
      out.set(Number(d), Number(st.slice(st.lastIndexOf(')') + 2).split(' ')[1]));
    } catch { /* the process ended */ }
  }
  return out;
}

/** `root` and every process descended from it (following PPid). @param {number} root @returns {number[]} */
export function processTree(root, ppid = parents()) {
  const tree = [root];
  for (let k = 0; k < tree.length; k++) for (const [pid, parent] of ppid) if (parent === tree[k]) tree.push(pid);
  return tree;
}

/** The Chromium processes under `root`. @param {number} root @returns {{pid: number, cmd: string[]}[]} */
function chromiums(root) {
  const out = [];
  for (const pid of processTree(root)) {
    try {
      const cmd = readFileSync(`/proc/${pid}/cmdline`, 'utf8').split('\0');
      if (/chrom/.test(cmd[0] || '')) out.push({ pid, cmd });
    } catch { /* the process ended */ }
  }
  return out;
}

/**
 * @param {number} root a process the browser descends from: this Node process (playwright starts the browser as its child)
 * @returns {Map<string, {kind: string, seconds: number}>} per pid/tid
 */
export function chromiumCpu(root = process.pid) {
  const out = new Map();
  for (const { pid, cmd } of chromiums(root)) {
    // Child processes rewrite their command line into one string (argv[0]).
    const type = cmd.join(' ').match(/--type=([a-z-]+)/)?.[1] ?? 'browser';
    let tids = [];
    try { tids = readdirSync(`/proc/${pid}/task`); } catch { continue; }
    for (const tid of tids) {
      try {
        const st = readFileSync(`/proc/${pid}/task/${tid}/stat`, 'utf8');
        const comm = st.slice(st.indexOf('(') + 1, st.lastIndexOf(')')).replace(/\d+$/, '');
        const f = st.slice(st.lastIndexOf(')') + 2).split(' ');
        out.set(`${pid}/${tid}`, { kind: `${type}: ${comm}`, seconds: (Number(f[11]) + Number(f[12])) / 100 });
      } catch { /* the thread ended */ }
    }
  }
  return out;
}

/** Resident memory of the Chromium processes under `root` (bytes). @param {number} root */
export function chromiumRss(root = process.pid) {
  let kb = 0;
  for (const { pid } of chromiums(root)) {
    try { kb += Number(readFileSync(`/proc/${pid}/status`, 'utf8').match(/^VmRSS:\s+(\d+)/m)?.[1] ?? 0); } catch { /* ended */ }
  }
  return kb * 1024;
}

/** CPU seconds per kind of thread between two snapshots, largest first, and their sum. */
export function cpuSince(before, after = chromiumCpu()) {
  const by = {};
  for (const [k, v] of after) by[v.kind] = (by[v.kind] || 0) + v.seconds - (before.get(k)?.seconds || 0);
  const kinds = Object.entries(by).filter(([, s]) => s >= 0.05).sort((a, b) => b[1] - a[1]);
  return { kinds, total: kinds.reduce((s, [, v]) => s + v, 0) };
}
