// Press-and-hold jog: a button held is StartMv along its axis at the chosen speed (percent of
// MaxSpeed); letting go, losing the pointer or hiding the page is StopMv.
export function setupJog(messd, log) {
  let held = null;
  const speed = () => Number(document.querySelector('input[name=speed]:checked').value);

  const release = () => {
    if (!held) return;
    held.classList.remove('held');
    held = null;
    messd.send('StopMv');
  };

  for (const button of document.querySelectorAll('.jog-button')) {
    button.addEventListener('pointerdown', async (ev) => {
      ev.preventDefault();
      if (held) release();
      button.setPointerCapture(ev.pointerId);
      held = button;
      button.classList.add('held');
      const v = [0, 0, 0];
      v[Number(button.dataset.axis)] = Number(button.dataset.dir) * speed();
      const reply = await messd.send('StartMv', v);
      if (reply.type === 'Err') {
        log(reply);
        if (held === button) { button.classList.remove('held'); held = null; }
      }
    });
    for (const end of ['pointerup', 'pointercancel', 'lostpointercapture']) button.addEventListener(end, release);
    button.addEventListener('contextmenu', (ev) => ev.preventDefault());  // a long touch is no menu
  }
  document.addEventListener('visibilitychange', () => { if (document.hidden) release(); });
  window.addEventListener('blur', release);
  return { jogging: () => held !== null };
}
