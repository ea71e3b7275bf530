// Press-and-hold jog: a button held is a jog along its axis at the chosen speed (percent of
// MaxSpeed); letting go, losing the pointer or hiding the page is StopMv. On a machine of
// exactly X Y Z the jog is StartMv; on any other (its AxPos names its axes: X Y C U V on the
// MRM arm, five on a 5-axis machine) it is JogAx with the axis' letter, and the page shows a
// pair of buttons for every axis it has, none for one it lacks.
export function setupJog(messd, log) {
  let held = null;
  let axes = null;  // the machine's letters when not exactly X Y Z (AxPos), else null
  const speed = () => Number(document.querySelector('input[name=speed]:checked').value);
  const extra = document.getElementById('jog-extra');

  const release = () => {
    if (!held) return;
    held.classList.remove('held');
    held = null;
    messd.send('StopMv');
  };

  async function press(button, ev) {
    ev.preventDefault();
    if (held) release();
    button.setPointerCapture(ev.pointerId);
    held = button;
    button.classList.add('held');
    const share = Number(button.dataset.dir) * speed();
    let reply;
    if (axes) {
      reply = await messd.send('JogAx', [`${button.dataset.letter}${share}`]);
    } else {
      const v = [0, 0, 0];
      v['XYZ'.indexOf(button.dataset.letter)] = share;
      reply = await messd.send('StartMv', v);
    }
    if (reply.type === 'Err') {
      log(reply);
      if (held === button) { button.classList.remove('held'); held = null; }
    }
  }

  function wire(button) {
    button.addEventListener('pointerdown', (ev) => press(button, ev));
    for (const end of ['pointerup', 'pointercancel', 'lostpointercapture']) button.addEventListener(end, release);
    button.addEventListener('contextmenu', (ev) => ev.preventDefault());  // a long touch is no menu
  }
  for (const button of document.querySelectorAll('.jog-button')) wire(button);

  // A machine whose axes are not exactly X Y Z: its X Y Z buttons only for the axes it has,
  // and a pair for each of its other axes.
  messd.on('AxPos', (e) => {
    const letters = e.axes.join(' ');
    if (letters === 'X Y Z' || axes === letters) return;
    axes = letters;
    for (const button of document.querySelectorAll('.jog .jog-button'))
      button.hidden = !e.axes.includes(button.dataset.letter);
    extra.replaceChildren(...e.axes.filter((a) => !'XYZ'.includes(a)).flatMap((letter) => [-1, 1].map((dir) => {
      const button = document.createElement('button');
      button.className = 'jog-button';
      button.id = `jog-${letter}${dir > 0 ? '+' : '-'}`;
      button.dataset.letter = letter;
      button.dataset.dir = String(dir);
      button.textContent = `${letter}${dir > 0 ? '+' : '−'}`;
      wire(button);
      return button;
    })));
  });
  document.addEventListener('visibilitychange', () => { if (document.hidden) release(); });
  window.addEventListener('blur', release);
  return { jogging: () => held !== null };
}
