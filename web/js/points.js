// The points as they arrive: the list, the top and front views with the probe, downloads.
export function setupPoints(messd) {
  const points = [];
  let probe = null;  // the probe's position (CurrCor)
  const body = document.querySelector('#points tbody');
  const count = document.getElementById('points-count');
  const top = document.getElementById('view-top');
  const front = document.getElementById('view-front');

  const known = new Set();  // hit numbers in the list: a replayed hit may also arrive live
  messd.on('Hit', (e) => {
    if (known.has(e.seq)) return;
    known.add(e.seq);
    points.push(e);
    const row = document.createElement('tr');
    row.className = 'new';
    row.dataset.seq = e.seq;
    row.dataset.shownAt = String(performance.timeOrigin + performance.now());  // wall clock, ms: the latency test reads it
    for (const text of [e.seq, e.x.toFixed(3), e.y.toFixed(3), e.z.toFixed(3),
      `${e.i.toFixed(3)} ${e.j.toFixed(3)} ${e.k.toFixed(3)}`]) {
      const cell = document.createElement('td');
      cell.textContent = text;
      row.appendChild(cell);
    }
    for (const old of body.querySelectorAll('tr.new')) old.classList.remove('new');
    body.prepend(row);
    count.textContent = String(points.length);
    draw();
  });
  messd.on('CurrCor', (e) => { probe = e; draw(); });

  // On connect, the journal's newest hits (up to 20), so the list does not start empty after a
  // reload: Replay from beyond the newest answers with the newest number, then Replay from there.
  messd.on('open', async () => {
    const newest = await messd.send('Replay', [1000000000000]);
    if (newest.type !== 'Ok' || newest.args.length < 2) return;
    const last = Number(newest.args[1]);
    if (last > 0) await messd.send('Replay', [Math.max(1, last - 19)]);
  });

  // Both views share one scale: the points and the probe, with room around them.
  function bounds() {
    const all = points.map((p) => [p.x, p.y, p.z]);
    if (probe) all.push([probe.x, probe.y, probe.z]);
    if (!all.length) return null;
    const lo = [0, 1, 2].map((a) => Math.min(...all.map((p) => p[a])));
    const hi = [0, 1, 2].map((a) => Math.max(...all.map((p) => p[a])));
    const span = Math.max(40, ...[0, 1, 2].map((a) => hi[a] - lo[a])) * 1.25;
    const mid = [0, 1, 2].map((a) => (lo[a] + hi[a]) / 2);
    return { mid, span };
  }

  function view(canvas, a, b, box) {
    const g = canvas.getContext('2d');
    g.clearRect(0, 0, canvas.width, canvas.height);
    if (!box) return;
    const s = Math.min(canvas.width, canvas.height) / box.span;
    const px = (p) => [canvas.width / 2 + (p[a] - box.mid[a]) * s, canvas.height / 2 - (p[b] - box.mid[b]) * s];
    g.fillStyle = '#1f5fbf';
    for (const p of points) {
      const [x, y] = px([p.x, p.y, p.z]);
      g.beginPath();
      g.arc(x, y, 3, 0, 2 * Math.PI);
      g.fill();
    }
    if (points.length) {  // the newest larger
      const p = points[points.length - 1];
      const [x, y] = px([p.x, p.y, p.z]);
      g.strokeStyle = '#d0021b';
      g.beginPath();
      g.arc(x, y, 6, 0, 2 * Math.PI);
      g.stroke();
    }
    if (probe) {
      const [x, y] = px([probe.x, probe.y, probe.z]);
      g.strokeStyle = '#2e8b57';
      g.lineWidth = 2;
      g.beginPath();
      g.arc(x, y, Math.max(4, 2 * s), 0, 2 * Math.PI);  // the 4 mm ball, at least visible
      g.stroke();
      g.lineWidth = 1;
    }
    g.fillStyle = '#667';
    g.fillText(canvas === top ? 'top: X → Y ↑' : 'front: X → Z ↑', 6, 12);
  }

  function draw() {
    const box = bounds();
    view(top, 0, 1, box);
    view(front, 0, 2, box);
  }

  function download(name, text) {
    const a = document.createElement('a');
    a.href = URL.createObjectURL(new Blob([text], { type: 'text/plain' }));
    a.download = name;
    a.click();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  }
  document.getElementById('download-csv').onclick = () => download('points.csv',
    'seq,x,y,z,i,j,k,r\n' + points.map((p) => [p.seq, p.x, p.y, p.z, p.i, p.j, p.k, p.r].join(',')).join('\n') + '\n');
  document.getElementById('download-xyz').onclick = () => download('points.xyz',
    points.map((p) => `${p.x.toFixed(4)} ${p.y.toFixed(4)} ${p.z.toFixed(4)}`).join('\n') + '\n');
  document.getElementById('clear-points').onclick = () => {
    points.length = 0;
    known.clear();
    body.replaceChildren();
    count.textContent = '0';
    draw();
  };
  return { points };
}
