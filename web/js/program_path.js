// The loaded program's path in the 3-D view: the web front end plans it as the program's check
// does ({"path":"loaded"}, docs/web.md) and the page draws its moves — rapid moves grey, feed
// moves teal, probing moves violet — and the moves of the source line the newest Block names
// in red. The view's element says what is drawn: data-path-segments (the planned segments),
// data-path-line (the line highlighted).
const kColours = { rapid: 0x9aa3b5, feed: 0x2a8c8c, probe: 0x8e44ad };
const kCurrent = 0xd0021b;

export class ProgramPath {
  constructor(messd, viewReady) {
    this.messd = messd;
    this.viewReady = viewReady;
    this.byLine = new Map();  // source line -> its lines in the scene
    this.line = null;
    this.wanted = null;  // the line the newest Block named (it may come before the path)
    this.box = document.getElementById('view3d');
  }

  // Asks for the loaded program's path and draws it (or removes it when `loaded` is false).
  async load(loaded) {
    const view = await this.viewReady;
    if (!view) return;
    this.byLine.clear();
    this.line = null;
    delete this.box.dataset.pathLine;
    if (!loaded) {
      delete this.box.dataset.pathSegments;
      return view.setExtra('program', null);
    }
    const reply = await this.messd.tool({ path: 'loaded' });
    if (reply.error) {
      delete this.box.dataset.pathSegments;
      return view.setExtra('program', null);
    }
    const { THREE } = view;
    const group = new THREE.Group();
    this.materials = {};
    for (const [kind, colour] of Object.entries(kColours)) this.materials[kind] = new THREE.LineBasicMaterial({ color: colour });
    this.current_material = new THREE.LineBasicMaterial({ color: kCurrent });
    for (const move of reply.moves) {
      const geometry = new THREE.BufferGeometry().setFromPoints(move.points.map((p) => new THREE.Vector3(p[0], p[1], p[2])));
      const line = new THREE.Line(geometry, this.materials[move.kind] || this.materials.feed);
      line.userData = { kind: move.kind };
      group.add(line);
      if (!this.byLine.has(move.line)) this.byLine.set(move.line, []);
      this.byLine.get(move.line).push(line);
    }
    this.box.dataset.pathSegments = String(reply.segments);
    view.setExtra('program', group);
    view.frame();
    if (this.wanted !== null) this.current(this.wanted);
  }

  // Highlights the moves of source line `line` (null: none).
  async current(line) {
    this.wanted = line;
    const view = await this.viewReady;
    if (!view || line === this.line) return;
    for (const l of this.byLine.get(this.line) || []) l.material = this.materials[l.userData.kind];
    this.line = line;
    const now = this.byLine.get(line) || [];
    for (const l of now) l.material = this.current_material;
    if (line === null) delete this.box.dataset.pathLine;
    else this.box.dataset.pathLine = String(line);
    view.render();
  }
}
