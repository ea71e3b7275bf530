# IMESS inspection from FreeCAD, without the GUI: the plan's features (to give captured points
# the feature they measure), `messcap inspect PLAN --points FILE` on those points, and a live
# `messcap inspect PLAN HOST:PORT` run that measures the plan on the machine while the panel
# captures its points. The report is coloured by imess_deviation.
"""Inspection plans and messcap inspect runs (testable under freecadcmd)."""

import json
import os
import subprocess
import tempfile

from imess_capture import CaptureError, find_messcap, signed_um


def read_plan(path):
    """{"part": name, "features": [(name, type), ...]} of an inspection plan (docs/metrology.md §14);
    messcap checks the rest when it runs."""
    try:
        with open(path) as f:
            plan = json.load(f)
    except (OSError, ValueError) as e:
        raise CaptureError("cannot read the inspection plan %s: %s" % (path, e))
    features = plan.get("features") if isinstance(plan, dict) else None
    if not isinstance(features, list) or not all(isinstance(f, dict) and isinstance(f.get("name"), str) for f in features):
        raise CaptureError("%s is not an inspection plan: it needs \"features\": [{\"name\": …, \"type\": …}, …] "
                           "(docs/metrology.md §14)" % path)
    return {"part": str(plan.get("part", os.path.basename(path))),
            "features": [(f["name"], str(f.get("type", ""))) for f in features]}


def points_text(objects):
    """The lines `messcap inspect --points` reads for the objects that have a plan feature:
    `FEATURE x y z i j k r` for a hit (its approach and tip radius: messcap compensates the
    probe along the fitted normal), `FEATURE x y z` for a point without. Returns (text, used,
    skipped): how many points went in and how many had no feature."""
    lines, skipped = [], 0
    for o in objects:
        if not hasattr(o, "Measured"):
            continue
        feature = getattr(o, "Feature", "")
        if not feature:
            skipped += 1
            continue
        p = o.Measured
        if hasattr(o, "Approach") and hasattr(o, "TipRadius"):
            a = o.Approach
            lines.append("%s %r %r %r %r %r %r %r" % (feature, p.x, p.y, p.z, a.x, a.y, a.z, o.TipRadius))
        else:
            lines.append("%s %r %r %r" % (feature, p.x, p.y, p.z))
    return "".join(line + "\n" for line in lines), len(lines), skipped


def inspect_points(plan, objects, messcap=None):
    """`messcap inspect PLAN --points FILE --json OUT` on the objects that have a feature;
    returns (OUT's path, points used, points skipped)."""
    if not os.path.isfile(plan):
        raise CaptureError("inspection plan %s not found" % plan)
    text, used, skipped = points_text(objects)
    if not used:
        raise CaptureError("none of the %d points has a feature of the plan: choose the feature for new points "
                           "before measuring them, or select points, choose their feature and press Assign" % skipped)
    work = tempfile.mkdtemp(prefix="imess-inspect-")
    points_path, out_path = os.path.join(work, "points.txt"), os.path.join(work, "inspection.json")
    with open(points_path, "w") as f:
        f.write(text)
    r = subprocess.run([messcap or find_messcap(), "inspect", plan, "--points", points_path, "--json", out_path],
                       capture_output=True, text=True, timeout=60)
    if not os.path.isfile(out_path):  # a report with characteristics out of tolerance is still a report
        raise CaptureError(r.stderr.strip() or "messcap inspect wrote no report (exit %d)" % r.returncode)
    return out_path, used, skipped


class PlanRun:
    """`messcap inspect PLAN HOST:PORT --json OUT` measuring the plan on the machine the session
    is connected to, without blocking: start(), then tick() from the panel's timer until
    `state` is "done" (report = OUT) or "failed" (error = why). messcap takes control; when this
    panel holds it, it is released first. Progress lines go to the session's events ("inspect")."""

    def __init__(self, plan, session, messcap=None):
        self.plan, self.session = plan, session
        self.messcap = messcap
        self.state = "new"
        self.proc = None
        self.report = self.error = None
        self.work = tempfile.mkdtemp(prefix="imess-measure-")
        self.log_path = os.path.join(self.work, "messcap.log")
        self.log_seen = 0

    def start(self):
        if not os.path.isfile(self.plan):
            raise CaptureError("inspection plan %s not found" % self.plan)
        if not self.session.connected():
            raise CaptureError("connect to messd first: messcap measures the plan on the machine the panel is connected to")
        self.exe = self.messcap or find_messcap()
        if self.session.holds_control():
            self.state = "releasing"  # messcap's Take would be refused while the panel holds control
            self.session.observers.append(self.on_line)
            self.session.send("Release")
            self.session.events.post("inspect", "releasing control for messcap")
        else:
            self.launch()

    def on_line(self, line, answered):
        if answered == "Release" and self.state == "releasing":
            self.session.observers.remove(self.on_line)
            if line.startswith("Ok"):
                self.launch()
            else:
                self.finish_failed("could not release control for messcap: %s" % line)

    def launch(self):
        self.out = os.path.join(self.work, "inspection.json")
        with open(self.log_path, "w") as log:
            self.proc = subprocess.Popen([self.exe, "inspect", self.plan, "%s:%d" % (self.session.host, self.session.port),
                                          "--json", self.out], stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT)
        self.state = "running"
        self.session.events.post("inspect", "messcap measures %s" % os.path.basename(self.plan))

    def progress(self):
        """Lines messcap wrote since the last call."""
        try:
            with open(self.log_path, encoding="utf-8", errors="replace") as f:
                f.seek(self.log_seen)
                text = f.read()
        except OSError:
            return []
        complete = text[: text.rfind("\n") + 1]
        self.log_seen += len(complete.encode("utf-8"))
        return [line for line in complete.splitlines() if line.strip()]

    def tick(self):
        if self.state != "running":
            return self.state
        for line in self.progress():
            if line.startswith("messcap: "):
                self.session.events.post("inspect", line[len("messcap: "):])
        code = self.proc.poll()
        if code is None:
            return self.state
        self.progress()
        if os.path.isfile(self.out):  # exit 5: some characteristic out of tolerance - still a report
            self.report, self.state = self.out, "done"
            self.session.events.post("inspect", "messcap measured %s (exit %d)" % (os.path.basename(self.plan), code))
        else:
            with open(self.log_path, encoding="utf-8", errors="replace") as f:
                lines = [line for line in f.read().splitlines() if line.strip()]
            self.finish_failed(lines[-1] if lines else "messcap inspect ended with exit %d and no report" % code)
        return self.state

    def finish_failed(self, why):
        self.state, self.error = "failed", why
        self.session.events.post("inspect", "inspection failed: %s" % why)

    def cancel(self, why):
        """Ends a running messcap (closing its connection stops what it commanded)."""
        if self.state == "releasing":
            self.session.observers.remove(self.on_line)
        if self.proc is not None and self.proc.poll() is None:
            self.proc.terminate()
            self.proc.wait(5)
        if self.state in ("releasing", "running"):
            self.state = "failed"
            self.error = why
            self.session.events.post("inspect", "inspection stopped: %s" % why)


def characteristic_row(c):
    """(name, 'ok: 29.9999 mm, deviation -0.1 µm, tolerance ±20.0 µm') of one report
    characteristic, the verdict first (a narrow panel cuts the end); lengths to 0.1 µm, angles to 0.0001°."""
    name = str(c.get("name", "?"))
    if "actual" not in c:
        return name, "not evaluated: %s" % c.get("error", "no value")
    if c.get("unit") == "deg":
        value, dev = "%.4f°" % c["actual"], "%+.4f°" % (round(c["deviation"], 4) + 0.0)
        tol = "%+.4f° … %+.4f°" % (c.get("lower", 0), c.get("upper", 0))
    else:
        value, dev = "%.4f mm" % c["actual"], signed_um(c["deviation"])
        lower, upper = c.get("lower", 0) * 1000, c.get("upper", 0) * 1000
        if c.get("zone"):
            tol = "≤ %.1f µm" % upper
        elif abs(lower + upper) < 1e-9:
            tol = "±%.1f µm" % upper
        else:
            tol = "%+.1f … %+.1f µm" % (lower, upper)
    verdict = "ok" if c.get("in_tolerance") else "OUT"
    return name, "%s: %s, deviation %s, tolerance %s" % (verdict, value, dev, tol)


def summary_text(summary, count):
    """'characteristics: 13 ok, 0 OUT' (and how many not evaluated, when any) from a report's summary."""
    if not isinstance(summary, dict):
        return "%d characteristics" % count
    text = "characteristics: %d ok, %d OUT" % (summary.get("in_tolerance", 0), summary.get("out_of_tolerance", 0))
    missing = summary.get("not_evaluated", 0)
    return text + (", %d not evaluated" % missing if missing else "")
