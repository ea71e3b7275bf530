# Inside freecadcmd: points coloured by deviation from a report in the shape `messcap inspect
# --json` writes (written here, so the test does not wait for that command): the colour scale,
# tolerance bands from characteristics or points, captured points coloured in place, the rest
# added, a second report replacing the first; the panel's Inspect button runs messcap inspect
# with the plan and the points (a stand-in messcap here records how it was called).
# argv: BIN_DIR SOURCE_DIR
import json
import os
import socket
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from plugin_test import Gui, check, finish, macro_namespace  # noqa: E402

import FreeCAD  # noqa: E402
import imess_capture  # noqa: E402
import imess_deviation as dev  # noqa: E402
from PySide import QtGui  # noqa: E402

V = FreeCAD.Vector
WORK = tempfile.mkdtemp(prefix="imess-freecad-deviation-")


def close(a, b, tol=1e-9):
    return all(abs(x - y) <= tol for x, y in zip(a, b))


def scale_checks():
    c = dev.deviation_colour
    check(c(0.0, 0.1) == dev.GREEN, "0 is green")
    check(close(c(0.05, 0.1), dev.YELLOW) and close(c(0.1, 0.1), dev.RED) and close(c(0.3, 0.1), dev.RED),
          "without a band: yellow at half the scale, red at the scale and beyond")
    check(close(c(-0.05, 0.1), dev.CYAN) and close(c(-0.1, 0.1), dev.BLUE), "negative: cyan, then blue")
    def from_green(rgb):
        return sum((a - g) ** 2 for a, g in zip(rgb, dev.GREEN)) ** 0.5

    for d in (0.01, 0.03, 0.07):  # symmetric: -d as far from green as +d, on the cold side
        plus, minus = c(d, 0.1), c(-d, 0.1)
        check(abs(from_green(plus) - from_green(minus)) < 1e-12 and plus[2] == 0 and minus[0] == 0 and
              from_green(plus) > 0, "symmetric around 0 at %g: %s / %s" % (d, plus, minus))
    band = (-0.02, 0.05)
    check(c(0.051, 1.0, band) == dev.RED and c(-0.021, 1.0, band) == dev.BLUE, "outside the band: red above, blue below")
    check(close(c(0.05, 1.0, band), dev.YELLOW) and c(0.0, 1.0, band) == dev.GREEN, "in the band: green to yellow at upper")
    inside = c(-0.02, 1.0, band)  # lower limit: 0.4 of the way to cyan (the scale is +-0.05)
    check(close(inside, dev._mix(dev.GREEN, dev.CYAN, 0.4)) and inside not in (dev.RED, dev.BLUE),
          "in the band the scale is symmetric too (+-max(|lower|, |upper|)): %s" % (inside,))


def captured_points(doc, xyz):
    ours, daemon = socket.socketpair()
    s = imess_capture.CaptureSession(doc, sock=ours)
    daemon.sendall("".join("MeasPt %.3f %.3f %.3f\n" % p for p in xyz).encode())
    s.poll()
    return s.points


REPORT = {
    "plan": "block.plan",
    "points": [
        {"feature": "top", "xyz": [10.0, 10.0, 80.0004], "deviation": 0.012},
        {"feature": "top", "xyz": [90.0, 10.0, 79.97], "deviation": -0.03},
        {"feature": "bore", "xyz": [475.0, 350.0, 40.0], "deviation": 0.015},
        {"feature": "bore", "xyz": [445.0, 350.0, 40.0], "deviation": 0.03, "tolerance": [-0.01, 0.04]},
        {"feature": "slot", "xyz": [1.0, 2.0, 3.0], "deviation": -0.06},
    ],
    "characteristics": [
        {"name": "top flat", "feature": "top", "measured": 0.042},
        {"name": "top profile", "feature": "top", "lower": -0.02, "upper": 0.02, "ok": False},
        {"name": "bore D", "feature": "bore", "tolerance": 0.02},
    ],
}


def colouring_checks():
    doc = FreeCAD.newDocument("deviation")
    pts = captured_points(doc, [(10, 10, 80), (90, 10, 79.97), (475, 350, 40), (445, 350, 40), (0, 0, 0)])
    path = os.path.join(WORK, "inspection.json")
    with open(path, "w") as f:
        json.dump(REPORT, f)
    summary = dev.colour_points(doc, path)
    check(summary == {"points": 5, "matched": 4, "added": 1, "out_of_tolerance": 1, "scale": 0.06},
          "summary %s" % summary)
    top1, top2, bore1, bore2, untouched = pts
    check(top1.Deviation == 0.012 and top1.Feature == "top" and (top1.ToleranceLower, top1.ToleranceUpper) == (-0.02, 0.02),
          "a point within 0.001 mm is the captured one; the band is the first characteristic of its feature with one")
    check(top1.InTolerance and not top2.InTolerance, "-0.03 is outside -0.02 .. 0.02")
    check(close(top1.DeviationColor[:3], dev.deviation_colour(0.012, 0.06, (-0.02, 0.02)), 1e-6) and
          close(top2.DeviationColor[:3], dev.BLUE, 1e-6), "colours from the band: %s %s"
          % (top1.DeviationColor, top2.DeviationColor))
    check((bore1.ToleranceLower, bore1.ToleranceUpper) == (-0.02, 0.02) and bore1.InTolerance,
          "\"tolerance\": t is +-t")
    check((bore2.ToleranceLower, bore2.ToleranceUpper) == (-0.01, 0.04) and bore2.InTolerance,
          "a point's own tolerance wins over its feature's")
    check("Deviation" not in untouched.PropertiesList, "a point not in the report stays as captured")
    group = doc.getObject(dev.DEVIATION_GROUP)
    added = group.Group if group else []
    check(len(added) == 1 and added[0].Shape.Vertexes[0].Point == V(1, 2, 3) and added[0].Label == "slot -0.0600"
          and "ToleranceLower" not in added[0].PropertiesList and close(added[0].DeviationColor[:3], dev.BLUE, 1e-6),
          "a point nobody captured is added, coloured on the +-0.06 scale without a band")

    again = dev.colour_points(doc, {"points": [{"feature": "top", "xyz": [90.0, 10.0, 79.97], "deviation": 0.001}]})
    check(again["matched"] == 1 and not doc.getObject(dev.DEVIATION_GROUP).Group, "a new report removes the added points")
    check("Deviation" not in top1.PropertiesList and top2.Deviation == 0.001 and "ToleranceLower" not in top2.PropertiesList,
          "and the earlier colours and bands: %s" % top2.PropertiesList)

    for bad, words in (({"characteristics": []}, "no \"points\" list"),
                       ({"points": [{"feature": "a", "xyz": [1, 2], "deviation": 0}]}, "\"xyz\" must be [x, y, z]"),
                       ({"points": [{"feature": "a", "xyz": [1, 2, 3], "deviation": "big"}]}, "deviation must be a number"),
                       ({"points": [{"feature": "a", "xyz": [1, 2, 3], "deviation": 0, "lower": 1}]}, "give both"),
                       ({"points": [{"feature": "a", "xyz": [1, 2, 3], "deviation": 0, "tolerance": [1, -1]}]},
                        "lower 1 is above upper -1")):
        try:
            dev.colour_points(doc, bad)
            check(False, "%s is refused" % bad)
        except imess_capture.CaptureError as e:
            check(words in str(e), "%r says %r" % (str(e), words))
    FreeCAD.closeDocument(doc.Name)


FAKE_INSPECT = '''#!/usr/bin/python3
# messcap inspect PLAN --points FILE --json OUT, as the plugin calls it: records argv and the
# points, writes a report giving each point the deviation z - 40.
import json, sys
args = sys.argv[1:]
json.dump({"argv": args, "points": open(args[3]).read()}, open(%(record)r, "w"))
pts = [[float(v) for v in line.split()] for line in open(args[3]) if line.strip()]
json.dump({"points": [{"feature": "bore", "xyz": p, "deviation": p[2] - 40} for p in pts],
           "characteristics": [{"feature": "bore", "tolerance": 0.5}]}, open(args[5], "w"))
'''


def panel_checks():
    ns, warnings, _ = macro_namespace()
    doc = FreeCAD.newDocument("inspectpanel")
    pts = captured_points(doc, [(475, 350, 40.2), (445, 350, 39.1)])
    record = os.path.join(WORK, "argv.json")
    fake = os.path.join(WORK, "messcap")
    with open(fake, "w") as f:
        f.write(FAKE_INSPECT % {"record": record})
    os.chmod(fake, 0o755)
    plan = os.path.join(WORK, "block.plan")
    open(plan, "w").write("a plan\n")
    panel = ns["CapturePanel"]()
    check(not panel.inspect_button.isEnabled(), "Inspect waits for a plan")
    QtGui.QFileDialog.getOpenFileName = staticmethod(lambda *a, **k: (plan, ""))
    panel.choose_plan()
    check(panel.inspect_button.isEnabled() and panel.plan_label.text() == "block.plan", "a chosen plan enables Inspect")
    Gui.selected = []
    real = os.environ["IMESS_MESSCAP"]
    os.environ["IMESS_MESSCAP"] = fake
    try:
        panel.inspect()
    finally:
        os.environ["IMESS_MESSCAP"] = real
    called = json.load(open(record)) if os.path.exists(record) else {"argv": []}
    argv = called["argv"]
    check(len(argv) == 6 and argv[:2] == ["inspect", plan] and argv[2] == "--points" and argv[4] == "--json",
          "messcap inspect PLAN --points FILE --json OUT: %s" % argv)
    check(called.get("points", "").split("\n")[:2] == ["475.0 350.0 40.2", "445.0 350.0 39.1"],
          "every captured point went to inspect: %r" % called.get("points"))
    check(not warnings and abs(pts[0].Deviation - 0.2) < 1e-9 and pts[0].InTolerance and not pts[1].InTolerance,
          "the report coloured the captured points (warnings: %s)" % warnings)
    check(panel.status.text() == "2 points coloured (2 captured, 0 added), 1 out of tolerance", panel.status.text())

    report = os.path.join(WORK, "by-hand.json")
    json.dump({"points": [{"feature": "x", "xyz": [475, 350, 40.2], "deviation": -0.3}]}, open(report, "w"))
    QtGui.QFileDialog.getOpenFileName = staticmethod(lambda *a, **k: (report, ""))
    panel.open_report()
    check(pts[0].Deviation == -0.3 and "Deviation" not in pts[1].PropertiesList, "Report... colours from a file")
    json.dump({"nothing": 1}, open(report, "w"))
    panel.open_report()
    check(len(warnings) == 1 and "no \"points\" list" in warnings[0], "a bad report is shown: %s" % warnings)
    FreeCAD.closeDocument(doc.Name)


finish("freecad deviation", scale_checks, colouring_checks, panel_checks)
