// The points as they arrive: the list, the 3-D view with the probe, downloads.
import { createView3d } from './view3d.js';

export function setupPoints(messd) {
  const points = [];
  let probe = null;  // the probe's position (CurrCor)
  let tipRadius = 2;  // the newest hit's, mm
  let view = null;    // the 3-D view, once three.js has loaded
  const body = document.querySelector('#points tbody');
  const count = document.getElementById('points-count');
  const ready = createView3d(document.getElementById('view3d')).then((v) => {
    view = v;
    if (!view) return null;
    for (const p of points) view.addPoint(p);
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
