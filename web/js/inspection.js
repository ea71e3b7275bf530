// Inspection: the plans of the programs folder (NAME.plan.json) and a plan run by messcap
// itself (`messcap inspect`, started by messd's web front end as a client of its own, docs/web.md):
// the page gives up control so messcap can take it, then shows messcap's table and the very
// HTML report messcap wrote.
export function setupInspection(messd, log) {
  const list = document.getElementById('plan-list');
  const status = document.getElementById('inspect-status');
  const table = document.getElementById('inspect-table');
  const frame = document.getElementById('inspect-report');
  const button = document.getElementById('inspect-run');

  async function refresh() {
    const reply = await messd.tool({ inspect: 'list' });
    if (reply.error) return;
    const chosen = list.value;
    list.replaceChildren(...reply.plans.map((name) => new Option(name, name)));
    if (reply.plans.includes(chosen)) list.value = chosen;
  }

  button.onclick = async () => {
    if (!list.value) return;
    button.disabled = true;
    status.className = 'note';
    status.textContent = `messcap inspect ${list.value}: measuring…`;
    table.textContent = '';
    frame.removeAttribute('src');
    frame.hidden = true;
    await messd.send('Release');  // messcap takes control; refused when the page does not hold it: fine
    const reply = await messd.tool({ inspect: 'run', plan: list.value });
    button.disabled = false;
    if (reply.error) {
      status.textContent = reply.error;
      status.className = 'note err';
      return log({ type: 'Err', line: `inspect: ${reply.error}` });
    }
    const verdict = { 0: 'every characteristic in tolerance', 5: 'out of tolerance or not evaluated' }[reply.status]
      ?? `failed (exit status ${reply.status})`;
    status.textContent = `messcap inspect ${reply.plan}: ${verdict}`;
    status.className = reply.status === 0 ? 'note' : 'note err';
    status.dataset.status = String(reply.status);
    table.textContent = reply.table + (reply.status === 0 || reply.status === 5 ? '' : reply.messages);
    if (reply.report) {
      frame.src = `${reply.report}?t=${Date.now()}`;
      frame.hidden = false;
    }
  };
  document.getElementById('plan-refresh').onclick = refresh;
  messd.on('open', refresh);
}
