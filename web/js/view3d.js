// The 3-D view: the points, the newest marked, and the probe, in the machine's coordinates (Z
// up), orbited with the mouse or a finger (three.js's OrbitControls). three.js is Debian's
// libjs-three, which messd serves as /three/ (docs/web.md); without it the view says so and the
// rest of the page works. Drawn on demand, not in a loop. The container carries what the scene
// holds (data-points, data-last, data-probe: "x y z"), which the browser test reads.
const kPoint = 0x1f5fbf;
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
  // The points: one cloud (one draw call however many there are) and the newest as a ball.
  let capacity = 256;
  let count = 0;
  let positions = new Float32Array(capacity * 3);
  const cloudGeometry = new THREE.BufferGeometry();
  cloudGeometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  cloudGeometry.setDrawRange(0, 0);
  const cloud = new THREE.Points(cloudGeometry, new THREE.PointsMaterial({ color: kPoint, size: 5, sizeAttenuation: false }));
  cloud.frustumCulled = false;
  scene.add(cloud);
  const newest = new THREE.Mesh(ball, new THREE.MeshLambertMaterial({ color: kNewest }));
  newest.visible = false;
  scene.add(newest);
  const bounds = new THREE.Box3();  // of every point
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
  controls.addEventListener('start', () => { follow = false; });
  const inView = (v) => framed && framed.containsPoint(v);

  // At most five drawings a second: the position comes many times a second, and a tablet
  // without a fast GPU (or a software one: headless Chromium's) must keep time for the page's
  // messages and its dead-man keep-alives. Orbiting by hand draws at once.
  let due = false;
  let drawn = 0;
  function render() {
    if (due) return;
    due = true;
    setTimeout(() => requestAnimationFrame(() => { due = false; drawn = performance.now(); draw(); }),
      Math.max(0, drawn + 200 - performance.now()));
  }

  function draw() {
    renderer.render(scene, camera);
    box.dataset.points = String(count);
    box.dataset.last = count ? fmt(newest.position) : '';
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
    controls.update();
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

  controls.addEventListener('change', draw);
  window.addEventListener('resize', resize);
  resize();

  const view = {
    THREE,
    addPoint(p) {
      if (count === capacity) {  // the cloud's buffer, twice as large
        capacity *= 2;
        const grown = new Float32Array(capacity * 3);
        grown.set(positions);
        positions = grown;
        cloudGeometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
      }
      positions.set([p.x, p.y, p.z], count * 3);
      count += 1;
      cloudGeometry.setDrawRange(0, count);
      cloudGeometry.attributes.position.needsUpdate = true;
      newest.position.set(p.x, p.y, p.z);
      newest.scale.setScalar(size * 1.8);
      newest.visible = true;
      bounds.expandByPoint(newest.position);
      if (follow && (!inView(newest.position) || count <= 2)) frame();
      render();
    },
    clearPoints() {
      count = 0;
      cloudGeometry.setDrawRange(0, 0);
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
