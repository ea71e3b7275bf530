// The scans' summary in the points panel: a line per scan (its id, its points so far, the hit
// numbers they span, whether it ended), never a row per point — a scan brings hundreds of points a
// second. The lines are redrawn at most five times a second, as the 3-D view. Each line carries
// data-id and data-points, which the browser test reads.
export function createScanList(list) {
  const scans = [];        // { id, points, first, last, ended, item }, oldest first
  const open = new Map();  // id -> the scan of that id still running
  let due = null;

  function show() {
    due = null;
    for (const s of scans) {
      if (!s.dirty) continue;
      s.dirty = false;
      s.item.dataset.points = String(s.points);
      s.item.textContent = `scan ${s.id}: ${s.points} point${s.points === 1 ? '' : 's'} (${s.first}–${s.last})${s.ended ? ` ${s.ended}` : ' …'}`;
    }
  }
  const later = () => { if (!due) due = setTimeout(show, 200); };

  return {
    // A Scan event (not seen before): counted in its scan's line; a new line when its id has none
    // running.
    add(e) {
      let s = open.get(e.id);
      if (!s) {
        s = { id: e.id, points: 0, first: e.seq, last: e.seq, ended: '', item: document.createElement('li') };
        s.item.dataset.id = String(e.id);
        s.item.className = 'scan';
        scans.push(s);
        open.set(e.id, s);
        list.prepend(s.item);
      }
      s.points += 1;
      s.last = e.seq;
      s.dirty = true;
      later();
    },
    // Done or Failed of a queued id: its scan, if one runs, has ended.
    end(id, how) {
      const s = open.get(id);
      if (!s) return;
      open.delete(id);
      s.ended = how;
      s.dirty = true;
      later();
    },
    clear() {
      scans.length = 0;
      open.clear();
      list.replaceChildren();
    },
  };
}
