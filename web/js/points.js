// The points as they arrive: the list, the 3-D view with the probe, downloads; the scans' points
// as a cloud in the view and a line per scan (scans.js).
import { createView3d } from './view3d.js';
import { createScanList } from './scans.js';

export function setupPoints(messd) {
  const points = [];
  let probe = null;  // the probe's position (CurrCor)
  let tipRadius = 2;  // the newest hit's, mm
  let view = null;    // the 3-D view, once three.js has loaded
  const body = document.querySelector('#points tbody');
  const count = document.getElementById('points-count');
  const scanList = createScanList(document.getElementById('scans'));
  let scanWaiting = [];  // scan points that came before the view: drawn once it is there
  let loading = true;    // three.js not loaded yet (without it, no view: nothing waits)
  const ready = createView3d(document.getElementById('view3d')).then((v) => {
    view = v;
    loading = false;
    if (!view) { scanWaiting = []; return null; }
    for (const p of points) view.addPoint(p);
    for (const p of scanWaiting) view.addScanPoint(p);
    scanWaiting = [];
    if (probe) view.setProbe(probe, tipRadius);
    document.getElementById('view-fit').onclick = () => view.frame();
    window.imessView3d = view;  // for the browser tests
    return view;
  });

  const known = new Set();  // hit numbers in the list: a replayed hit may also arrive live
  messd.on('Hit', (e) => {
    if (known.has(e.seq)) return;
    known.add(e.seq);
    points.push(e);
    const row = document.createElement('tr');
    row.className = 'new';
    row.dataset.seq = e.seq;
    row.dataset.shownAt = String(performance.timeOrigin + performance.now());  // wall clock, ms: the latency test reads it
    row.onclick = () => row.classList.toggle('selected');  // the selection to fit or download
    for (const text of [e.seq, e.x.toFixed(3), e.y.toFixed(3), e.z.toFixed(3),
      `${e.i.toFixed(3)} ${e.j.toFixed(3)} ${e.k.toFixed(3)}`]) {
      const cell = document.createElement('td');
      cell.textContent = text;
      row.appendChild(cell);
    }
    for (const old of body.querySelectorAll('tr.new')) old.classList.remove('new');
    body.prepend(row);
    count.textContent = String(points.length);
    if (e.r > 0) tipRadius = e.r;
    if (view) view.addPoint(e);
  });
  // A scan's point: into the view's cloud and its scan's line, not into the list (which holds
  // hits). The hit numbers are shared: a point replayed and live is counted once.
  messd.on('Scan', (e) => {
    if (known.has(e.seq)) return;
    known.add(e.seq);
    scanList.add(e);
    if (view) view.addScanPoint(e);
    else if (loading) scanWaiting.push({ x: e.x, y: e.y, z: e.z });
  });
  messd.on('Done', (e) => scanList.end(e.id, 'done'));
  messd.on('Failed', (e) => scanList.end(e.id, `failed: ${e.reason}`));
  messd.on('CurrCor', (e) => {
    probe = e;
    if (view) view.setProbe(e, tipRadius);
  });

  // On connect, the journal's newest hits (up to 20), so the list does not start empty after a
  // reload: Replay from beyond the newest answers with the newest number, then Replay from there.
  messd.on('open', async () => {
    const newest = await messd.send('Replay', [1000000000000]);
    if (newest.type !== 'Ok' || newest.args.length < 2) return;
    const last = Number(newest.args[1]);
    if (last > 0) await messd.send('Replay', [Math.max(1, last - 19)]);
  });

  document.getElementById('clear-points').onclick = () => {
    points.length = 0;
    known.clear();
    body.replaceChildren();
    count.textContent = '0';
    scanList.clear();
    scanWaiting = [];
    if (view) view.clearPoints();
  };
  // The selected points, oldest first (all when none is selected), as the page got them.
  function selection() {
    const chosen = new Set([...body.querySelectorAll('tr.selected')].map((r) => Number(r.dataset.seq)));
    return chosen.size ? points.filter((p) => chosen.has(p.seq)) : points.slice();
  }
  document.getElementById('select-all').onclick = () => {
    for (const r of body.rows) r.classList.add('selected');
  };
  document.getElementById('select-none').onclick = () => {
    for (const r of body.rows) r.classList.remove('selected');
  };
  return { points, ready, selection };
}
