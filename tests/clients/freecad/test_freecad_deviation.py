# Inside freecadcmd: points coloured by deviation from an inspection report, the report read as
# `messcap inspect --json` writes it: the colour scale, each point's scale and verdict from the
# characteristics of its feature (a zone of width t is +-t/2 around the point's deviation, a
# distance its limits; a point is out of tolerance only when its feature's characteristics are),
# captured points found at the report's machine coordinates (its "xyz" is in part coordinates),
# the rest added there, a second report replacing the first, refused reports; the Report...
# button. The reports here are written by hand to hold the cases; messcap's own reports, live
# and from points, are coloured in test_freecad_inspect.py. argv: BIN_DIR SOURCE_DIR
import json
import os
import socket
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from plugin_test import check, finish, panel_module  # noqa: E402

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
    check(close(c(0.05, 0.1), dev._mix(dev.GREEN, dev.YELLOW, 0.5)) and close(c(0.1, 0.1), dev.YELLOW),
          "toward yellow, yellow at the scale")
    check(close(c(-0.05, 0.1), dev._mix(dev.GREEN, dev.CYAN, 0.5)) and close(c(-0.1, 0.1), dev.CYAN),
          "negative: toward cyan")
    check(close(c(0.3, 0.1), dev.YELLOW) and close(c(-0.3, 0.1), dev.CYAN), "beyond the scale, in tolerance: no red, no blue")
    check(c(0.3, 0.1, out=True) == dev.RED and c(-0.3, 0.1, out=True) == dev.BLUE,
          "beyond the scale and out of tolerance: red above, blue below")
    check(close(c(0.05, 0.1, out=True), dev._mix(dev.GREEN, dev.YELLOW, 0.5)),
          "a point within its scale is not red even when its feature is out")

    def from_green(rgb):
        return sum((a - g) ** 2 for a, g in zip(rgb, dev.GREEN)) ** 0.5

    for d in (0.01, 0.03, 0.07):  # symmetric: -d as far from green as +d, on the cold side
        plus, minus = c(d, 0.1), c(-d, 0.1)
        check(abs(from_green(plus) - from_green(minus)) < 1e-12 and plus[2] == 0 and minus[0] == 0 and
              from_green(plus) > 0, "symmetric around 0 at %g: %s / %s" % (d, plus, minus))

    s = dev.characteristic_scale
    check(s({"type": "flatness", "zone": True, "lower": 0, "upper": 0.01, "unit": "mm"}, "c") == 0.005,
          "a zone of width 0.01 is +-0.005 around a point")
    check(s({"type": "size", "zone": False, "lower": -0.02, "upper": 0.02, "unit": "mm"}, "c") == 0.01,
          "a diameter's +-0.02 is +-0.01 on the radius a point shows")
    check(s({"type": "size", "zone": False, "lower": -0.1, "upper": 0.1, "unit": "mm", "radius": True}, "c") == 0.1,
          "a radius's limits as they are")
    check(s({"type": "distance", "zone": False, "lower": -0.03, "upper": 0.05, "unit": "mm"}, "c") == 0.05,
          "a distance: its larger limit")
    check(s({"type": "angle", "zone": False, "lower": -0.05, "upper": 0.05, "unit": "deg"}, "c") is None,
          "an angle says nothing about a point's millimetres")


def captured_points(doc, hits):
    """Points captured from Hit + MeasPt lines on a socket pair, each [x, y, z]."""
    ours, daemon = socket.socketpair()
    s = imess_capture.CaptureSession(doc, sock=ours)
    daemon.sendall("".join("Hit %d 0 %.4f %.4f %.4f 0.000000 0.000000 -1.000000 2.0000 1.000000\nMeasPt %.3f %.3f %.3f\n"
                           % ((i + 1,) + tuple(p) + tuple(p)) for i, p in enumerate(hits)).encode())
    s.poll()
    return s.points


def zone(name, feature, width, ok, kind="flatness"):
    return {"name": name, "type": kind, "feature": feature, "unit": "mm", "zone": True, "lower": 0, "upper": width,
            "in_tolerance": ok, "actual": 0.0, "deviation": 0.0, "nominal": 0.0}


# As messcap writes it: "xyz" in part coordinates (the part frame at 400 300 0), "machine" where
# the point was measured.
REPORT = {
    "part": "block",
    "points": [
        {"feature": "top", "xyz": [20.0, 25.0, 80.0], "machine": [420.0, 325.0, 80.0], "deviation": -0.000001, "form": 0.0},
        {"feature": "top", "xyz": [100.0, 20.0, 80.0], "machine": [500.0, 320.0, 80.0], "deviation": 0.004, "form": 0.004},
        {"feature": "bore", "xyz": [75.0, 50.0, 40.0], "machine": [475.0, 350.0, 40.0], "deviation": 0.012},
        {"feature": "bore", "xyz": [45.0, 50.0, 40.0], "machine": [445.0, 350.0, 40.0], "deviation": -0.003},
        {"feature": "slot", "xyz": [1.0, 2.0, 3.0], "machine": [401.0, 302.0, 3.0], "deviation": -0.06},
    ],
    "characteristics": [
        zone("top flatness", "top", 0.01, True),
        {"name": "top parallelism", "type": "parallelism", "feature": "top", "datum": "bottom", "unit": "mm", "zone": True,
         "lower": 0, "upper": 0.02, "in_tolerance": True},
        {"name": "bore diameter", "type": "size", "feature": "bore", "unit": "mm", "zone": False, "lower": -0.02,
         "upper": 0.02, "in_tolerance": True, "nominal": 30.0, "actual": 30.0123, "deviation": 0.0123},
        {"name": "bore position", "type": "position", "feature": "bore", "unit": "mm", "zone": True, "lower": 0,
         "upper": 0.05, "error": "feature 'bore' has no fit: …"},
        zone("bore roundness", "bore", 0.01, False, "roundness"),
        {"name": "height", "type": "distance", "feature": "bottom", "other": "top", "unit": "mm", "zone": False,
         "lower": -0.05, "upper": 0.05, "in_tolerance": True},
    ],
    "summary": {"characteristics": 6, "in_tolerance": 4, "out_of_tolerance": 1, "not_evaluated": 1},
}


def colouring_checks():
    doc = FreeCAD.newDocument("deviation")
    pts = captured_points(doc, [(420, 325, 80), (500, 320, 80), (475, 350, 40), (445, 350, 40), (430, 330, 80)])
    path = os.path.join(WORK, "inspection.json")
    with open(path, "w") as f:
        json.dump(REPORT, f)
    summary = dev.colour_points(doc, path)
    check((summary["points"], summary["matched"], summary["added"], summary["out_of_tolerance"]) == (5, 4, 1, 2),
          "found at the machine coordinates: %s" % {k: v for k, v in summary.items() if k != "report"})
    top1, top2, bore1, bore2, untouched = pts
    check(top1.InTolerance and top2.InTolerance and top1.Scale == 0.005 and close(top1.DeviationColor[:3], dev.GREEN, 1e-3),
          "a zone is +-half its width around a point: -1 nm of a flat top is in tolerance, green (%s)" % (top1.DeviationColor,))
    check(close(top2.DeviationColor[:3], dev._mix(dev.GREEN, dev.YELLOW, 0.8), 1e-5), "0.004 of 0.005: near yellow")
    check(top1.Characteristics == "top flatness ok, top parallelism ok, height ok",
          "a point lists the characteristics of its feature, a distance on both features: %r" % top1.Characteristics)
    check(top1.Feature == "top" and top1.Label == "MeasPt001 top +0.0 µm" and top2.Label == "MeasPt002 top +4.0 µm",
          "the feature and the deviation in µm in the label: %r %r" % (top1.Label, top2.Label))
    check(not bore1.InTolerance and not bore2.InTolerance and bore1.Scale == 0.005,
          "the bore's roundness is out: its points are out of tolerance; its scale the tightest, roundness +-0.005")
    check(close(bore1.DeviationColor[:3], dev.RED, 1e-6) and
          close(bore2.DeviationColor[:3], dev._mix(dev.GREEN, dev.CYAN, 0.6), 1e-5),
          "red only beyond the scale (0.012), a point within it (-0.003) stays toward cyan: %s %s"
          % (bore1.DeviationColor, bore2.DeviationColor))
    check("Deviation" not in untouched.PropertiesList and untouched.Label == "MeasPt005", "a point not in the report stays")
    group = doc.getObject(dev.DEVIATION_GROUP)
    added = group.Group if group else []
    check(len(added) == 1 and added[0].Shape.Vertexes[0].Point == V(401, 302, 3) and added[0].Label == "Deviation slot -60.0 µm"
          and "InTolerance" not in added[0].PropertiesList and added[0].Scale == 0.005
          and close(added[0].DeviationColor[:3], dev.CYAN, 1e-6),
          "a point nobody captured is added where it was measured; a feature without characteristics: the tightest "
          "scale of the others, no verdict, so no blue")
    alone = dev.read_report({"points": [{"feature": "a", "xyz": [0, 0, 0], "deviation": d} for d in (0.002, -0.004)]})
    check(dev.judge(alone["points"][0], alone["features"], 0.004) == (0.004, None, ""),
          "a report without characteristics: the largest deviation is the scale")

    again = dev.colour_points(doc, {"points": [{"feature": "top", "xyz": [100, 20, 80], "machine": [500, 320, 80],
                                                "deviation": 0.001, "tolerance": [-0.0005, 0.0005]}]})
    check(again["matched"] == 1 and not doc.getObject(dev.DEVIATION_GROUP).Group, "a new report removes the added points")
    check("Deviation" not in top1.PropertiesList and top1.Label == "MeasPt001 top" and top2.Deviation == 0.001,
          "and the earlier colours: %s" % top1.PropertiesList)
    check((top2.ToleranceLower, top2.ToleranceUpper) == (-0.0005, 0.0005) and not top2.InTolerance and
          close(top2.DeviationColor[:3], dev.RED, 1e-6), "a point's own band (a report written by hand) judges it")
    old_style = dev.colour_points(doc, {"points": [{"feature": "top", "xyz": [420, 325, 80], "deviation": 0.0}]})
    check(old_style["matched"] == 1, "a report without \"machine\" is placed by its \"xyz\"")

    for bad, words in (({"characteristics": []}, "no \"points\" list"),
                       ({"points": [{"feature": "a", "xyz": [1, 2], "deviation": 0}]}, "\"xyz\" must be [x, y, z]"),
                       ({"points": [{"feature": "a", "machine": [1, 2, "3"], "deviation": 0}]}, "\"machine\" must be a number"),
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


def panel_checks():
    """Report...: a report file chosen in the panel colours the points and lists the
    characteristics with µm; a bad one is shown."""
    mod, warnings, _ = panel_module()
    doc = FreeCAD.newDocument("reportpanel")
    pts = captured_points(doc, [(475, 350, 40), (445, 350, 40)])
    panel = mod.CapturePanel()
    check(not panel.inspect_button.isEnabled() and not panel.measure_plan_button.isEnabled(), "Inspect waits for a plan")
    report = os.path.join(WORK, "by-hand.json")
    with open(report, "w") as f:
        json.dump(REPORT, f)
    QtGui.QFileDialog.getOpenFileName = staticmethod(lambda *a, **k: (report, ""))
    panel.open_report()
    check(pts[0].Deviation == 0.012 and pts[1].Deviation == -0.003, "Report... colours from a file")
    check(panel.events.text("colour") == "5 points coloured (3 added: not captured here), 2 out; "
          "characteristics: 4 ok, 1 OUT, 1 not evaluated", panel.events.text("colour"))
    rows = dict(panel.results())
    check(rows.get("top flatness") == "ok: 0.0000 mm, deviation +0.0 µm, tolerance ≤ 10.0 µm" and
          rows.get("bore roundness") == "OUT: 0.0000 mm, deviation +0.0 µm, tolerance ≤ 10.0 µm" and
          rows.get("bore diameter") == "ok: 30.0123 mm, deviation +12.3 µm, tolerance ±20.0 µm" and
          rows.get("bore position") == "not evaluated: feature 'bore' has no fit: …" and
          [name for name, _ in panel.results()] == [c["name"] for c in REPORT["characteristics"]],
          "the characteristics in the panel, in the report's order: %s" % rows)
    with open(report, "w") as f:
        json.dump({"nothing": 1}, f)
    panel.open_report()
    check(len(warnings) == 1 and "no \"points\" list" in warnings[0] and "no \"points\" list" in panel.events.text("inspect"),
          "a bad report is shown: %s" % warnings)
    FreeCAD.closeDocument(doc.Name)


finish("freecad deviation", scale_checks, colouring_checks, panel_checks)
