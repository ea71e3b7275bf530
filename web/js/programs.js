// Programs: the folder's list, Load with the check's summary or its error, Run, Pause,
// Resume, Abort, the current block and the progress; the loaded program's path in the 3-D view
// (program_path.js), its current line highlighted.
import { ProgramPath } from './program_path.js';

export function setupPrograms(messd, log, viewReady) {
  const path = new ProgramPath(messd, viewReady);
  const list = document.getElementById('program-list');
  const check = document.getElementById('program-check');
  const progress = document.getElementById('program-progress');
  const block = document.getElementById('program-block');

  const show = (reply) => {
    check.textContent = reply.line;
    check.classList.toggle('err', reply.type === 'Err');
    if (reply.type === 'Err') log(reply);
    return reply;
  };

  async function refresh() {
    const reply = await messd.send('Programs');
    if (reply.type !== 'Ok') return show(reply);
    const chosen = list.value;
    list.replaceChildren(...reply.args.map((name) => new Option(name, name)));
    if (reply.args.includes(chosen)) list.value = chosen;
  }

  document.getElementById('program-refresh').onclick = refresh;
  document.getElementById('program-load').onclick = async () => {
    if (!list.value) return;
    progress.value = 0;
    block.textContent = '';
    const reply = show(await messd.send('Load', [list.value]));
    path.load(reply.type === 'Ok');
  };
  document.getElementById('program-run').onclick = async () => {
    const reply = show(await messd.send('Run'));
    if (reply.type === 'Ok') path.load(true);  // Run checks again from where the machine stands
  };
  document.getElementById('program-pause').onclick = async () => show(await messd.send('Pause'));
  document.getElementById('program-resume').onclick = async () => show(await messd.send('Resume'));
  document.getElementById('program-abort').onclick = async () => show(await messd.send('Abort'));

  messd.on('Block', (e) => {
    progress.max = e.blocks;
    progress.value = e.block;
    block.textContent = `${e.name} line ${e.src_line} block ${e.block}/${e.blocks}`;
    path.current(e.src_line);
  });
  messd.on('ProgPause', (e) => { block.textContent = `${e.name} paused at line ${e.src_line}: ${e.reason}`; });
  messd.on('ProgEnd', (e) => {
    if (e.result === 'ok') progress.value = progress.max;
    block.textContent = `ProgEnd ${e.name} ${e.result} line ${e.src_line} ${e.text}`;
    block.classList.toggle('err', e.result !== 'ok');
    path.current(null);
  });
  messd.on('open', refresh);
  messd.on('open', async () => {  // a program loaded before the page was: its path
    const program = await messd.send('Program');
    if (program.type === 'Ok' && program.args[0] && program.args[0] !== 'none') path.load(true);
  });
}
