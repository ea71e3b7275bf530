// The WebSocket to messd (docs/web.md): commands go as {"cmd":VERB,"args":[...]}, every
// line messd sends comes as a JSON event. Replies come in the order of the requests, so each
// send() is answered by the next Ok or Err; the Data lines before it travel with it.
export class Messd {
  constructor(url) {
    this.url = url;
    this.listeners = new Map();
    this.pending = [];
    this.data = [];
    this.tools = new Map();  // id -> the resolver of a points request (tool())
    this.nextTool = 1;
    this.connect();
  }

  connect() {
    const ws = new WebSocket(this.url);
    this.ws = ws;
    ws.onopen = () => this.emit('open', {});
    ws.onmessage = (m) => this.dispatch(JSON.parse(m.data));
    ws.onclose = () => {
      for (const p of this.pending) p({ type: 'Err', code: 0, text: 'the connection to messd closed', data: [] });
      this.pending = [];
      this.data = [];
      for (const [id, t] of this.tools) t({ type: 'Err', id, error: 'the connection to messd closed' });
      this.tools.clear();
      this.emit('close', {});
      setTimeout(() => this.connect(), 1000);  // messd restarted, the network came back: again
    };
  }

  get open() { return this.ws && this.ws.readyState === WebSocket.OPEN; }

  dispatch(e) {
    if (['Export', 'Fit', 'Path', 'Inspect'].includes(e.type) && this.tools.has(e.id)) {  // the web front end's own answers
      this.tools.get(e.id)(e);
      this.tools.delete(e.id);
    }
    if ((e.type === 'Ok' || e.type === 'Err') && this.pending.length) {
      e.data = this.data;
      e.reply = true;  // the answer to a send(): its caller shows it
      this.data = [];
      this.pending.shift()(e);
    } else if (this.pending.length && (e.type === 'Data')) {
      this.data.push(e);
    }
    this.emit(e.type, e);
    this.emit('*', e);
  }

  on(type, fn) {
    if (!this.listeners.has(type)) this.listeners.set(type, []);
    this.listeners.get(type).push(fn);
  }

  emit(type, e) {
    for (const fn of this.listeners.get(type) || []) fn(e);
  }

  // A command; resolves to its reply event (Ok or Err).
  send(cmd, args = []) { return this.post({ cmd, args }); }
  // A line as typed.
  line(text) { return this.post({ line: text }); }

  post(message) {
    if (!this.open) return Promise.resolve({ type: 'Err', code: 0, text: 'not connected to messd', data: [] });
    this.ws.send(JSON.stringify(message));
    return new Promise((resolve) => this.pending.push(resolve));
  }

  // A request the web front end answers itself ({"export":…}, {"fit":…}, {"path":…},
  // {"inspect":…}, docs/web.md): resolves to its answer, which carries "error" when it failed.
  tool(message) {
    if (!this.open) return Promise.resolve({ type: 'Err', error: 'not connected to messd' });
    const id = this.nextTool++;
    this.ws.send(JSON.stringify({ ...message, id }));
    return new Promise((resolve) => this.tools.set(id, resolve));
  }

  // The blank line: the dead-man's keep-alive, no reply.
  keepAlive() {
    if (this.open) this.ws.send('{"cmd":""}');
  }
}
