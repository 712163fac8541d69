// CPU seconds used by Chromium's threads (Linux /proc), by process type and
// thread name: what a run of the page costs the machine, whatever else runs
// on it (wall time on a shared machine says little; CPU / cores is a floor).
import { readFileSync, readdirSync } from 'node:fs';

/** @returns {Map<string, {kind: string, seconds: number}>} per pid/tid */
export function chromiumCpu() {
  const out = new Map();
  for (const pid of readdirSync('/proc').filter((d) => /^\d+$/.test(d))) {
    let cmd;
    try { cmd = readFileSync(`/proc/${pid}/cmdline`, 'utf8').split('\0'); } catch { continue; }
    if (!/chrom/.test(cmd[0] || '')) continue;
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

/** CPU seconds per kind of thread between two snapshots, largest first, and their sum. */
export function cpuSince(before, after = chromiumCpu()) {
  const by = {};
  for (const [k, v] of after) by[v.kind] = (by[v.kind] || 0) + v.seconds - (before.get(k)?.seconds || 0);
  const kinds = Object.entries(by).filter(([, s]) => s >= 0.05).sort((a, b) => b[1] - a[1]);
  return { kinds, total: kinds.reduce((s, [, v]) => s + v, 0) };
}
