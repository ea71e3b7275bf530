// messd's web panel: the page wired to the WebSocket (docs/web.md). Every button is a MESSD
// command; the page shows what messd says, never what it expects.
import { Messd } from './messd.js';
import { setupJog } from './jog.js';
import { setupPoints } from './points.js';
import { setupPointTools } from './point_tools.js';
import { setupPrograms } from './programs.js';
import { setupInspection } from './inspection.js';

const $ = (id) => document.getElementById(id);
const token = new URLSearchParams(location.search).get('token');
const url = `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws${token ? `?token=${encodeURIComponent(token)}` : ''}`;
const messd = new Messd(url);

// The log: refusals (Err), warnings, faults and the console's replies, newest last.
function log(e) {
  const item = document.createElement('li');
  item.className = e.type;
  item.textContent = e.line || `${e.type} ${e.code ?? ''} ${e.text ?? ''}`;
  const list = $('log');
  list.appendChild(item);
  while (list.children.length > 200) list.firstChild.remove();
  list.scrollTop = list.scrollHeight;
}

// The dead-man: messd stops the machine when this page says nothing for 1.5 s (a hung
// browser); a closed tab closes the socket, which stops it at once. Keep-alives every 250 ms
// (a hidden tab's timers may slow to 1 s; the jog stops when the page is hidden anyway).
let keepAlive = null;
messd.on('open', async () => {
  $('link').textContent = 'online';
  $('link').className = 'badge on';
  await messd.send('Hello', ['web']);
  await messd.send('Watch', [1500]);
  clearInterval(keepAlive);
  keepAlive = setInterval(() => messd.keepAlive(), 250);
});
messd.on('close', () => {
  $('link').textContent = 'offline';
  $('link').className = 'badge off';
  clearInterval(keepAlive);
});

messd.on('CurrCor', (e) => {
  $('pos-X').textContent = e.x.toFixed(3);
  $('pos-Y').textContent = e.y.toFixed(3);
  $('pos-Z').textContent = e.z.toFixed(3);
});
messd.on('AxPos', (e) => {  // a machine not of exactly X Y Z: its X Y Z large (those it has), the others below
  for (const a of 'XYZ') $(`pos-${a}`).parentElement.hidden = !e.axes.includes(a);
  const extra = $('axes-extra');
  extra.replaceChildren(...e.axes.flatMap((axis, n) => ('XYZ'.includes(axis) ? [] : [n])).map((n) => {
    const axis = e.axes[n];
    const box = document.createElement('div');
    box.innerHTML = `<span>${axis}</span><output id="pos-${axis}x"></output>`;
    box.querySelector('output').textContent = e.pos[n].toFixed(3);
    return box;
  }));
});
messd.on('State', (e) => { $('state').textContent = e.state; });
messd.on('Control', (e) => { $('control').textContent = e.name === null ? 'none' : `${e.name}@${e.host}`; });
messd.on('Frame', (e) => { $('frame').textContent = e.name === 'machine' ? '' : `frame ${e.name}`; });
for (const type of ['Warn', 'Fault', 'Limit', 'Homed']) messd.on(type, log);
messd.on('Err', (e) => { if (!e.reply) log(e); });  // no command's answer: a refusal at connect, a drop
messd.on('*', (e) => {
  if (e.type !== 'CurrCor' && e.type !== 'AxPos' && e.type !== 'Ok') $('last').textContent = e.line;
});
messd.on('open', async () => {  // the state and the holder as they are now
  const status = await messd.send('Status');
  if (status.type !== 'Ok') return;
  const at = status.args.indexOf('State');
  if (at >= 0) $('state').textContent = status.args[at + 1];
  const c = status.args.indexOf('Control');
  if (c >= 0) $('control').textContent = status.args[c + 1];
});

const reply = async (promise) => { const r = await promise; if (r.type === 'Err') log(r); return r; };
$('stop').onclick = () => reply(messd.send('StopMv'));
$('take').onclick = () => reply(messd.send('Take'));
$('release').onclick = () => reply(messd.send('Release'));
$('measure-here').onclick = () => reply(messd.send('ForcePt'));
$('stats-refresh').onclick = async () => {
  const r = await reply(messd.send('Stats'));
  if (r.type !== 'Ok') return;
  const pairs = [];  // "Period 1000", "LatP50 12" ...
  for (let i = 0; i + 1 < r.args.length; i += 2) pairs.push(`${r.args[i]} ${r.args[i + 1]}`);
  $('stats').textContent = pairs.join('\n');
};
$('console').onsubmit = async (ev) => {
  ev.preventDefault();
  const text = $('console-line').value.trim();
  if (!text) return;
  $('console-line').value = '';
  const r = await messd.line(text);
  for (const d of r.data) log(d);
  log(r);
};

setupJog(messd, log);
const pointList = setupPoints(messd);
setupPointTools(messd, pointList, log);
setupPrograms(messd, log, pointList.ready);
setupInspection(messd, log);
window.imess = messd;  // for the browser tests and the curious: the connection
