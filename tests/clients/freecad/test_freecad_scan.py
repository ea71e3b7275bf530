# Inside freecadcmd: the plugin's panel captures scans as point clouds. A real messd with the
# measuring probe (the scanning machine, brisk and in loop time); another client touches the top
# once and scans a quarter of the Ø 30 bore at 20 mm/s, then the same id again. The document must
# hold a Points::Feature Scan_5 with exactly the points of the Scan lines messd sent, in order,
# their hit numbers and outward normals, filled in batches (far fewer recomputes than points); the
# touch stays a MeasPt of its own; the repeated id is a cloud of its own; the cloud fits (Ø 30). argv: BIN_DIR SOURCE_DIR
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from plugin_test import Messd, Operator, check, connect_panel, finish, panel_module, pump  # noqa: E402

import FreeCAD  # noqa: E402
import imess_fit  # noqa: E402
import imess_scan  # noqa: E402

QUARTER = "ScanCirc %d 460 350 60 475 350 60 0 0 1 90 bore 20"


class Recomputes:
    """Counts the recomputes of one document (a FreeCAD document observer)."""

    def __init__(self, doc):
        self.doc, self.count = doc, 0

    def slotRecomputedDocument(self, doc):  # noqa: N802 - FreeCAD's name
        if doc == self.doc:
            self.count += 1


def scan_checks():
    mod, warnings, app = panel_module()
    messd = Messd(scanning=True)
    doc = FreeCAD.newDocument("scan")
    panel = mod.CapturePanel()
    panel.show()
    check(connect_panel(panel, app, messd.port), "Connect: %s" % panel.events.lines())
    s = panel.session
    recomputes = Recomputes(doc)
    FreeCAD.addDocumentObserver(recomputes)
    scans = {}  # id -> the Scan lines the operator received

    def operator():
        op.touch("top", 0, 0, -50)
        op.go_to(460, 350, 100)
        op.go_to(460, 350, 60)
        for scan_id in (5, 5):
            lines = []
            op.request(QUARTER % scan_id)
            while True:
                line = op.line()
                if line.startswith("Scan "):
                    lines.append(line)
                elif line.startswith(("Done %d" % scan_id, "Failed %d" % scan_id)):
                    break
            scans.setdefault(scan_id, []).append(lines)
            op.ended = line

    op = Operator(messd.port, script=operator)
    started = time.monotonic()
    op.start()
    ended = lambda: not op.is_alive() and all(c.Ended for c in s.scans.clouds) and len(s.scans.clouds) == 2  # noqa: E731
    check(pump(app, 20, ended) and op.error is None, "the operator touched once and scanned twice: %s %s"
          % (op.error, panel.events.lines()))
    elapsed = time.monotonic() - started
    FreeCAD.removeDocumentObserver(recomputes)

    first, again = scans.get(5, [[], []])
    n = len(first)
    cloud = doc.getObject("Scan_5")
    check(cloud is not None and cloud.TypeId == "Points::Feature" and cloud.InList[0].Name == imess_scan.SCAN_GROUP,
          "the scan is a Points::Feature Scan_5 in the group IMESS_Scans: %s" % (cloud and cloud.TypeId))
    if cloud is None or n == 0:
        return
    got = cloud.Points.Points
    words = [line.split() for line in first]
    sent = [FreeCAD.Vector(*[float(v) for v in w[3:6]]) for w in words]
    check(len(got) == n, "it holds exactly the %d points of the Scan lines messd sent: %d" % (n, len(got)))
    worst = max((a - b).Length for a, b in zip(got, sent)) if got else 1
    check(len(got) == n and worst < 1e-4, "each where its line says, in order (single precision: %.1e mm at most)" % worst)
    check(cloud.FirstHit == int(words[0][1]) and cloud.LastHit == int(words[-1][1]) and cloud.ScanId == 5 and
          cloud.Ended == "done", "its hit numbers %d-%d, id and end: %d-%d %d %r" % (
              int(words[0][1]), int(words[-1][1]), cloud.FirstHit, cloud.LastHit, cloud.ScanId, cloud.Ended))
    normal = [-float(v) for v in words[n // 2][6:9]]
    check(len(cloud.Normal) == n and (cloud.Normal[n // 2] - FreeCAD.Vector(*normal)).Length < 1e-6,
          "each point's outward normal, minus the line's i j k: %s" % (cloud.Normal[n // 2] if cloud.Normal else None))
    print("figures: %d scan points, %d recomputes of the document in %.2f s" % (n, recomputes.count, elapsed))
    check(0 < recomputes.count < n / 4, "the points come in batches: %d recomputes for %d points" % (recomputes.count, n))
    second = doc.getObject("Scan_5_2")
    check(second is not None and second.Points.CountPoints == len(again) > 0 and second.FirstHit > cloud.LastHit,
          "the id scanned again is a cloud of its own, Scan_5_2, with its %d points: %s" % (
              len(again), second and second.Points.CountPoints))
    check(len(s.points) == 1 and s.points[0].HitNumber < cloud.FirstHit and abs(s.points[0].Measured.z - 80) < 1e-3,
          "the touch stays a MeasPt of its own, the scans add none: %d" % len(s.points))
    total = n + len(again)
    check(s.scans.points == total and ("%d scanned" % total) in panel.state.text(),
          "the panel counts the scanned points: %r" % panel.state.text())
    check(any("Scan_5_2: %d points (done)" % len(again) in text for _, text in panel.events.lines()),
          "the events show the scan: %s" % panel.events.lines())
    circle = imess_fit.fit_feature(doc, "circle", [cloud])
    check(abs(circle.Diameter - 30) < 1e-3 and circle.PointCount == n,
          "the cloud fits as it is: a circle of its %d points, Ø %.4f" % (circle.PointCount, circle.Diameter))
    op.close()
    messd.stop()
    pump(app, 1, lambda: not s.connected())
    check(not warnings, "no warnings: %s" % warnings)
    FreeCAD.closeDocument(doc.Name)


finish("freecad scan", scan_checks)
