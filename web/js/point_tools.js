// The points' files and fits: the selected points (all when none is) go to the web front end,
// which answers with messcap's own writers and fits (docs/web.md "Points: files and fits"), so
// a download is the file `messcap -o points.csv` writes and a fit what `messcap fit` prints. The
// fitted feature is drawn in the 3-D view.
const v3 = (a) => a.map((x) => x.toFixed(3)).join(' ');

// A fit's result in words: the feature's position and size, then its form.
export function fitSummary(f) {
  const r = f.result;
  const parts = [`${f.kind} of ${f.n} points${f.probed ? ', probe-compensated' : ''}:`];
  if (r.center) parts.push(`centre ${v3(r.center)}`);
  if (r.point && !r.center) parts.push(`point ${v3(r.point)}`);
  if (r.diameter !== undefined) parts.push(`Ø ${r.diameter.toFixed(4)}`);
  if (r.normal) parts.push(`normal ${v3(r.normal)}`);
  if (r.axis) parts.push(`axis ${v3(r.axis)}`);
  if (r.direction) parts.push(`direction ${v3(r.direction)}`);
  parts.push(`rms ${r.rms.toFixed(4)} form ${r.form_min.toFixed(4)} .. ${r.form_max.toFixed(4)}`);
  return parts.join(' ');
}

// The fitted feature as lines in the scene (three.js from the view).
function featureLines(THREE, f, hits) {
  const r = f.result;
  const material = new THREE.LineBasicMaterial({ color: 0xe07b00 });
  const group = new THREE.Group();
  const vec = (a) => new THREE.Vector3(a[0], a[1], a[2]);
  // Two unit vectors across `n`.
  const across = (n) => {
    const a = Math.abs(n.z) < 0.9 ? new THREE.Vector3(0, 0, 1) : new THREE.Vector3(1, 0, 0);
    const u = new THREE.Vector3().crossVectors(n, a).normalize();
    return [u, new THREE.Vector3().crossVectors(n, u).normalize()];
  };
  const ring = (centre, n, radius) => {
    const [u, w] = across(n);
    const pts = [];
    for (let i = 0; i <= 64; i++) {
      const t = (i / 64) * 2 * Math.PI;
      pts.push(centre.clone().addScaledVector(u, radius * Math.cos(t)).addScaledVector(w, radius * Math.sin(t)));
    }
    return new THREE.Line(new THREE.BufferGeometry().setFromPoints(pts), material);
  };
  const along = (origin, axis) => hits.map((h) => new THREE.Vector3(h.x, h.y, h.z).sub(origin).dot(axis));
  if (f.kind === 'circle' || f.kind === 'circle2d') {
    group.add(ring(vec(r.center), vec(r.normal), r.diameter / 2));
  } else if (f.kind === 'sphere') {
    const c = vec(r.center);
    for (const n of [[0, 0, 1], [0, 1, 0], [1, 0, 0]]) group.add(ring(c, vec(n), r.diameter / 2));
  } else if (f.kind === 'cylinder' || f.kind === 'cone') {
    const origin = vec(r.point || r.apex);
    const axis = vec(r.axis);
    const t = along(origin, axis);
    const lo = Math.min(...t);
    const hi = Math.max(...t);
    const radius = (d) => (f.kind === 'cone' ? d * Math.tan((r.apex_angle_deg * Math.PI) / 360) : r.diameter / 2);
    for (const d of [lo, (lo + hi) / 2, hi]) group.add(ring(origin.clone().addScaledVector(axis, d), axis, radius(d)));
  } else if (f.kind === 'plane') {
    const p = vec(r.point);
    const n = vec(r.normal);
    const [u, w] = across(n);
    const size = Math.max(10, ...hits.map((h) => new THREE.Vector3(h.x, h.y, h.z).distanceTo(p))) * 1.2;
    const corners = [[-1, -1], [1, -1], [1, 1], [-1, 1], [-1, -1]].map(([a, b]) => p.clone().addScaledVector(u, a * size).addScaledVector(w, b * size));
    group.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(corners), material));
  } else if (f.kind === 'line' || f.kind === 'line2d') {
    const p = vec(r.point);
    const d = vec(r.direction);
    const t = along(p, d);
    group.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(
      [p.clone().addScaledVector(d, Math.min(...t)), p.clone().addScaledVector(d, Math.max(...t))]), material));
  }
  return group;
}

export function setupPointTools(messd, pointList, log) {
  const result = document.getElementById('fit-result');
  const resultLine = document.getElementById('fit-line');

  function download(name, text) {
    const a = document.createElement('a');
    a.href = URL.createObjectURL(new Blob([text], { type: 'text/plain' }));
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  }

  const hitsOf = (points) => points.map((p) => ({ seq: p.seq, x: p.x, y: p.y, z: p.z, i: p.i, j: p.j, k: p.k, r: p.r }));

  for (const format of ['csv', 'xyz', 'dmi', 'hits']) {
    document.getElementById(`download-${format}`).onclick = async () => {
      const points = pointList.selection();
      if (!points.length) return;
      const reply = await messd.tool({ export: format, hits: hitsOf(points) });
      if (reply.error) return log({ type: 'Err', line: `${format}: ${reply.error}` });
      download(reply.name, reply.text);
    };
  }

  document.getElementById('fit').onclick = async () => {
    const points = pointList.selection();
    const kind = document.getElementById('fit-kind').value;
    const reply = await messd.tool({ fit: kind, hits: hitsOf(points) });
    const view = await pointList.ready;
    result.classList.toggle('err', Boolean(reply.error));
    if (reply.error) {
      result.textContent = reply.error;
      resultLine.textContent = '';
      if (view) view.setExtra('fit', null);
      return;
    }
    result.textContent = fitSummary(reply);
    resultLine.textContent = reply.text;  // messcap fit's very line
    result.dataset.diameter = reply.result.diameter ?? '';
    if (view) view.setExtra('fit', featureLines(view.THREE, reply, points));
  };
}
