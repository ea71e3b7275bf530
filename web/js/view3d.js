// The 3-D view: the points, the newest marked, the scans' points as a cloud of their own
// colour, and the probe, in the machine's coordinates (Z up), orbited with the mouse or a finger
// (three.js's OrbitControls). three.js is Debian's libjs-three, which messd serves as /three/
// (docs/web.md); without it the view says so and the rest of the page works. Drawn on demand,
// not in a loop. The container carries what the scene holds (data-points, data-last,
// data-probe: "x y z", data-scan-points), which the browser test reads, and drawTimes() when
// the latest drawings were.
const kPoint = 0x1f5fbf;
const kScan = 0xc2185b;
const kNewest = 0xd0021b;
const kProbe = 0x2e8b57;

const fmt = (v) => `${v.x.toFixed(3)} ${v.y.toFixed(3)} ${v.z.toFixed(3)}`;

export async function createView3d(box) {
  let THREE;
  let OrbitControls;
  try {
    // The very URL OrbitControls imports three from, so the page holds one three.js.
    THREE = await import('/three/build/three.module.js');
    ({ OrbitControls } = await import('/three/examples/jsm/controls/OrbitControls.js'));
  } catch (e) {
    box.textContent = 'The 3-D view needs three.js: apt-get install libjs-three on the machine running messd.';
    box.classList.add('missing');
    return null;
  }
  // No antialiasing: a tablet without a fast GPU (or a software one) draws a frame in a few
  // ms, and the page's messages wait for none (scripts/bench web measures it).
  const renderer = new THREE.WebGLRenderer({ antialias: false });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xfbfcfe);
  box.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.add(new THREE.AmbientLight(0xffffff, 0.55));
  const sun = new THREE.DirectionalLight(0xffffff, 0.6);
  sun.position.set(1, -2, 3);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(40, 1, 0.1, 100000);
  camera.up.set(0, 0, 1);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.enableDamping = false;

  const ball = new THREE.SphereBufferGeometry(1, 16, 12);
  // The points: one cloud (one draw call however many there are) and the newest as a ball; the
  // scans' points another cloud. Each buffer is preallocated and doubled when full, drawn up to
  // its count (setDrawRange): tens of thousands of points are one array, no object per point.
  function growingCloud(color, pointSize) {
    const c = { capacity: 256, count: 0 };
    c.positions = new Float32Array(c.capacity * 3);
    c.geometry = new THREE.BufferGeometry();
    c.geometry.setAttribute('position', new THREE.BufferAttribute(c.positions, 3));
    c.geometry.setDrawRange(0, 0);
    c.points = new THREE.Points(c.geometry, new THREE.PointsMaterial({ color, size: pointSize, sizeAttenuation: false }));
    c.points.frustumCulled = false;
    scene.add(c.points);
    c.add = (x, y, z) => {
      if (c.count === c.capacity) {  // the buffer, twice as large
        c.capacity *= 2;
        const grown = new Float32Array(c.capacity * 3);
        grown.set(c.positions);
        c.positions = grown;
        c.geometry.setAttribute('position', new THREE.BufferAttribute(c.positions, 3));
      }
      c.positions[c.count * 3] = x;
      c.positions[c.count * 3 + 1] = y;
      c.positions[c.count * 3 + 2] = z;
      c.count += 1;
      c.geometry.setDrawRange(0, c.count);
      c.geometry.attributes.position.needsUpdate = true;
    };
    c.clear = () => {
      c.count = 0;
      c.geometry.setDrawRange(0, 0);
    };
    return c;
  }
  const cloud = growingCloud(kPoint, 5);
  const scanCloud = growingCloud(kScan, 3);
  const newest = new THREE.Mesh(ball, new THREE.MeshLambertMaterial({ color: kNewest }));
  newest.visible = false;
  scene.add(newest);
  const bounds = new THREE.Box3();  // of every point, the scans' too
  const scanPoint = new THREE.Vector3();
  const probe = new THREE.Group();  // the ball and its stem
  // See-through, so the point it has just touched shows.
  const tip = new THREE.Mesh(ball, new THREE.MeshLambertMaterial({ color: kProbe, transparent: true, opacity: 0.55 }));
  probe.add(tip);
  const stem = new THREE.Mesh(new THREE.CylinderBufferGeometry(0.35, 0.35, 1, 12), tip.material);
  stem.rotation.x = Math.PI / 2;  // along Z
  probe.add(stem);
  probe.visible = false;
  scene.add(probe);
  const axes = new THREE.AxesHelper(1);
  scene.add(axes);
  const extras = new THREE.Group();  // what other parts of the page draw (a program's path)
  scene.add(extras);

  let size = 2;        // a point's radius in mm, from the scene's extent
  let framed = null;   // the box the camera was put on (with room around it)
  let follow = true;   // the camera follows what is added until the user orbits; ⤢ again
  let framing = false; // frame() moves the camera: its change is drawn in turn, a hand's at once
  controls.addEventListener('start', () => { follow = false; });
  const inView = (v) => framed && framed.containsPoint(v);

  // At most five drawings a second: the position comes many times a second, and a tablet
  // without a fast GPU (or a software one: headless Chromium's) must keep time for the page's
  // messages and its dead-man keep-alives. Orbiting by hand draws at once.
  let due = false;
  let drawn = 0;
  const drawTimes = [];  // performance.now() of the latest 64 drawings: the browser test reads them
  function render() {
    if (due) return;
    due = true;
    const later = () => setTimeout(() => requestAnimationFrame(() => {
      const now = performance.now();
      if (now < drawn + 200) { later(); return; }  // a timer that fired early: the budget holds
      due = false;
      drawn = now;
      draw(now);
    }), Math.max(0, drawn + 200 - performance.now()));
    later();
  }

  function draw(now = performance.now()) {
    drawTimes.push(now);
    if (drawTimes.length > 64) drawTimes.shift();
    renderer.render(scene, camera);
    box.dataset.points = String(cloud.count);
    box.dataset.scanPoints = String(scanCloud.count);
    box.dataset.last = cloud.count ? fmt(newest.position) : '';
    box.dataset.probe = probe.visible ? fmt(probe.position) : '';
    box.dataset.extras = extras.children.map((o) => o.name).join(' ');
  }

  function resize() {
    const w = box.clientWidth || 300;
    const h = box.clientHeight || 260;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    render();
  }

  // The camera on everything there is, from the front left, above.
  function frame() {
    const all = bounds.clone();
    for (const o of extras.children) all.expandByObject(o);
    if (probe.visible) all.expandByPoint(probe.position);
    if (all.isEmpty()) return;
    const mid = all.getCenter(new THREE.Vector3());
    const span = Math.max(40, all.getSize(new THREE.Vector3()).length());
    controls.target.copy(mid);
    camera.position.copy(mid).add(new THREE.Vector3(-0.6, -1.2, 0.8).normalize().multiplyScalar(span * 1.6));
    camera.near = span / 1000;
    camera.far = span * 100;
    camera.updateProjectionMatrix();
    framing = true;  // the camera moved by the page, not by a hand: drawn within the budget
    controls.update();
    framing = false;
    size = span / 150;
    newest.scale.setScalar(size * 1.8);
    axes.position.copy(all.min);
    axes.scale.setScalar(span / 8);
    framed = all.clone().expandByScalar(span * 0.15);
    scaleProbe(tip.userData.radius || 2);
  }

  function scaleProbe(radius) {
    tip.userData.radius = radius;
    tip.scale.setScalar(Math.max(radius, size * 1.5));  // the ball, at least visible
    const length = Math.max(10, size * 12);
    stem.scale.set(1, length, 1);
    stem.position.set(0, 0, length / 2 + radius);
  }

  controls.addEventListener('change', () => (framing ? render() : draw()));
  window.addEventListener('resize', resize);
  resize();

  const view = {
    THREE,
    addPoint(p) {
      cloud.add(p.x, p.y, p.z);
      newest.position.set(p.x, p.y, p.z);
      newest.scale.setScalar(size * 1.8);
      newest.visible = true;
      bounds.expandByPoint(newest.position);
      if (follow && (!inView(newest.position) || cloud.count <= 2)) frame();
      render();
    },
    // A scan's point: into the scans' cloud; drawn with the next drawing (at most five a second).
    addScanPoint(p) {
      scanCloud.add(p.x, p.y, p.z);
      scanPoint.set(p.x, p.y, p.z);
      bounds.expandByPoint(scanPoint);
      if (follow && (!inView(scanPoint) || scanCloud.count <= 2)) frame();
      render();
    },
    clearPoints() {
      cloud.clear();
      scanCloud.clear();
      newest.visible = false;
      bounds.makeEmpty();
      if (follow) frame();
      render();
    },
    setProbe(p, radius = 2) {
      probe.position.set(p.x, p.y, p.z);
      probe.visible = true;
      scaleProbe(radius);
      if (follow && !inView(probe.position)) frame();
      render();
    },
    // Lines or meshes other parts of the page add (and replace) under a name.
    setExtra(name, object) {
      const old = extras.getObjectByName(name);
      if (old) extras.remove(old);
      if (object) { object.name = name; extras.add(object); }
      render();
    },
    frame() { follow = true; frame(); render(); },
    render,
    drawTimes: () => drawTimes.slice(),
    // The colour drawn where a point of the scene appears on the canvas: [r, g, b] (drawn and
    // read in one task: the drawing buffer is not kept after it is shown).
    pixelAt(x, y, z) {
      draw();
      const v = new THREE.Vector3(x, y, z).project(camera);
      const gl = renderer.getContext();
      const px = Math.round((v.x + 1) / 2 * gl.drawingBufferWidth);
      const py = Math.round((v.y + 1) / 2 * gl.drawingBufferHeight);
      const out = new Uint8Array(4);
      gl.readPixels(px, py, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
      return [out[0], out[1], out[2]];
    },
  };
  return view;
}
