#!/usr/bin/env python3
"""messcap inspect's HTML report, read by Chromium: the three views draw the nominal part (the
outline, every plane's extent, the bore), carry scale ticks, and their labels neither overlap
nor leave the picture as the browser lays the text out; a characteristic just out of tolerance
prints enough digits to show why (never "+0.0500 ... +0.0500 OUT").

Usage: check_inspect_html.py MESSCAP SOURCE_DIR [SCREENSHOT.png]
The points are the plan's nominal probe points on the machine with the right face 0.05004 mm
too far out. Needs chromium (Debian package, scripts/deps.sh). Exit 0 when every check holds.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

# Run in the page after it loaded: every view's labels and ticks as the browser measured them.
MEASURE = """
<script>
(function () {
  const out = [];
  for (const svg of document.querySelectorAll('svg.view')) {
    const vb = svg.viewBox.baseVal;
    const s = svg.getBoundingClientRect();
    const box = (t) => { const b = t.getBoundingClientRect(); return [b.x - s.x, b.y - s.y, b.width, b.height]; };
    out.push({
      caption: svg.parentElement.querySelector('figcaption').textContent,
      size: [vb.width, vb.height],
      labels: Array.from(svg.querySelectorAll('text.label')).map((t) => ({text: t.textContent, box: box(t)})),
      ticks: Array.from(svg.querySelectorAll('text.tick, text.axis-name')).map((t) => ({text: t.textContent, box: box(t)})),
      nominal: Array.from(svg.querySelectorAll('g.nominal > *')).map((e) => e.getAttribute('class')),
      titles: Array.from(svg.querySelectorAll('g.nominal title')).map((e) => e.textContent),
    });
  }
  const pre = document.createElement('pre');
  pre.id = 'imess-measured';
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
})();
</script>
"""


def chromium():
    for name in ("chromium", "chromium-browser"):
        path = shutil.which(name)
        if path:
            return path
    sys.exit("check_inspect_html: chromium not found; install the Debian package chromium (scripts/deps.sh does)")


def overlap(a, b):
    return a[0] < b[0] + b[2] and b[0] < a[0] + a[2] and a[1] < b[1] + b[3] and b[1] < a[1] + a[3]


def main(messcap, source, screenshot=None):
    failures = []

    def check(ok, what):
        if not ok:
            failures.append(what)

    plan_path = os.path.join(source, "examples", "cube-1996.plan.json")
    plan = json.load(open(plan_path))
    ox, oy, oz = plan["placement"]["origin"]
    work = tempfile.mkdtemp(prefix="imess-report-")
    points = os.path.join(work, "cube.txt")
    with open(points, "w") as f:
        for feature in plan["features"]:
            shift = 0.05004 if feature["name"] == "right" else 0.0
            for p in feature["probe"]:
                f.write("%s %.6f %.6f %.6f\n" % (feature["name"], p[0] + ox + shift, p[1] + oy, p[2] + oz))
    html = os.path.join(work, "cube.html")
    run = subprocess.run([messcap, "inspect", plan_path, "--points", points, "--html", html],
                         capture_output=True, text=True)
    table = run.stdout + run.stderr
    check(run.returncode == 5, "messcap inspect exit %d (5: out of tolerance), %s" % (run.returncode, table))

    # The verdict readable in the figures: the table and the page.
    length = [line for line in table.splitlines() if line.startswith("length ")]
    check(len(length) == 1 and "+0.05004" in length[0] and "+0.05000" in length[0] and "OUT" in length[0],
          "the table's length row shows why it is OUT: %r" % length)
    page = open(html).read()
    row = re.search(r"<tr><td>length</td>.*?</tr>", page)
    check(row and "+0.05004" in row.group(0) and "+0.05000" in row.group(0) and ">OUT<" in row.group(0),
          "the page's length row shows why it is OUT: %s" % (row.group(0) if row else "no row"))
    width = re.search(r"<tr><td>width</td>.*?</tr>", page)
    check(width and "+0.0500 mm" in width.group(0), "rows in tolerance keep four decimals")

    measured_html = os.path.join(work, "measured.html")
    with open(measured_html, "w") as f:
        f.write(page.replace("</body>", MEASURE + "</body>"))
    dump = subprocess.run([chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--virtual-time-budget=5000",
                           "--dump-dom", "file://" + measured_html], capture_output=True, text=True, timeout=120)
    found = re.search(r'<pre id="imess-measured">(.*?)</pre>', dump.stdout, re.S)
    if not found:
        print("check_inspect_html: Chromium gave no measurements:\n" + dump.stderr[-2000:])
        return 1
    views = json.loads(found.group(1).replace("&quot;", '"').replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&"))
    check(len(views) == 3, "three views, got %d" % len(views))
    for v in views:
        name = v["caption"]
        w, h = v["size"]
        check(v["nominal"].count("outline") == 1, "%s: the part's outline" % name)
        check(v["nominal"].count("plane") + v["nominal"].count("plane-face") == 6, "%s: the six planes" % name)
        check(v["nominal"].count("round") >= 3, "%s: the bore, its axis' cylinder and the fillet" % name)
        check(any(t.startswith("bore") for t in v["titles"]), "%s: the bore named" % name)
        numbers = [t for t in v["ticks"] if re.fullmatch(r"-?\d+(\.\d+)?", t["text"])]
        check(len(numbers) >= 6, "%s: scale ticks, got %s" % (name, [t["text"] for t in v["ticks"]]))
        texts = v["labels"] + v["ticks"]
        for t in texts:
            x, y, bw, bh = t["box"]
            check(x >= 0 and y >= 0 and x + bw <= w and y + bh <= h, "%s: '%s' leaves the picture at %s" % (name, t["text"], t["box"]))
        for i, a in enumerate(v["labels"]):
            for b in texts[i + 1:]:
                check(not overlap(a["box"], b["box"]), "%s: '%s' overlaps '%s'" % (name, a["text"], b["text"]))
        names = sorted(t["text"] for t in v["labels"])
        check(len(names) == len(set(names)) and len(names) >= 6, "%s: each feature labelled once: %s" % (name, names))

    if screenshot:
        subprocess.run([chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
                        "--window-size=1200,1000", "--screenshot=" + screenshot, "file://" + html],
                       capture_output=True, timeout=120)
    shutil.rmtree(work, ignore_errors=True)
    for f in failures:
        print("FAILED: " + f)
    print("check_inspect_html: %d checks failed" % len(failures) if failures else "check_inspect_html: all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    sys.exit(main(*sys.argv[1:]))
