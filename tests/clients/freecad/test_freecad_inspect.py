# Inside freecadcmd: the panel's inspection against a real messd and the real messcap.
# Measure plan: the panel, holding control after a jog, hands it to `messcap inspect PLAN HOST:PORT`,
# shows its progress, captures the 16 points it probes on the simulated cube (which stands turned
# 0.3°: part and machine coordinates differ), and colours every one of them from the report - all
# six characteristics in tolerance, so no point is out. Inspect: points an operator measured are
# given their plan features (Assign, and the feature for new points), `messcap inspect --points`
# evaluates them with their approach directions; a plan whose bore is drawn 0.1 mm too large
# makes the bore out of tolerance, and only its points turn red. argv: BIN_DIR SOURCE_DIR
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from plugin_test import (SHORT_PLAN, Gui, Messd, Operator, check, connect_panel, finish, mouse,  # noqa: E402
                         panel_module, pump)

import FreeCAD  # noqa: E402
import imess_deviation as dev  # noqa: E402

WORK = tempfile.mkdtemp(prefix="imess-freecad-inspect-")


def rows(panel):
    return dict(panel.results())


def live_checks():
    mod, warnings, app = panel_module()
    messd = Messd()
    try:
        doc = FreeCAD.newDocument("measureplan")
        panel = mod.CapturePanel()
        check(connect_panel(panel, app, messd.port), "Connect: %s" % panel.events.lines())
        s = panel.session
        mouse(panel.jog_buttons["+Z"], "press")
        pump(app, 2, lambda: s.state == "jog")
        mouse(panel.jog_buttons["+Z"], "release")
        check(pump(app, 3, lambda: s.state == "idle") and s.holds_control(), "after a jog the panel holds control")

        panel.choose_plan(SHORT_PLAN)
        check([panel.feature_box.itemText(i) for i in range(panel.feature_box.count())] ==
              ["(none)", "bottom", "front", "left", "top", "bore"] and panel.plan_label.text() ==
              "cube-short (cube-short.plan.json)", "the plan's features to choose from: %s" % panel.plan_label.text())
        panel.measure_plan()
        check(not panel.measure_plan_button.isEnabled(), "one run at a time")
        progress = []

        def running():
            text = panel.events.text("inspect")
            if text and (not progress or progress[-1] != text):
                progress.append(text)
            return panel.run is None

        pump(app, 100, running)
        check(progress[:3] == ["releasing control for messcap", "messcap measures cube-short.plan.json",
                               "measuring cube-short on 127.0.0.1:%d (tip radius 2 mm, feed 300 mm/s)" % messd.port]
              and "part frame from bottom, front, left: origin 400.2626 299.6866 0.0000, x axis turned 0.3000 deg about z"
              in progress and progress[-1].startswith("messcap measured cube-short.plan.json (exit 0)"),
              "control handed over, messcap's progress shown: %s" % progress)
        check(len(s.points) == 16 and all(getattr(o, "HitNumber", 0) > 0 for o in s.points),
              "the 16 points messcap probed were captured as they came: %d" % len(s.points))
        check(panel.events.text("colour") == "16 points coloured, 0 out; characteristics: 6 ok, 0 OUT",
              "all found at their machine coordinates (none added): %s"
              % panel.events.text("colour"))
        features = [o.Feature for o in s.points]
        check(features == ["bottom"] * 3 + ["front"] * 3 + ["left"] * 3 + ["top"] * 3 + ["bore"] * 4,
              "each point knows its feature from the report: %s" % features)
        judged = [o for o in s.points if o.Feature in ("bottom", "top", "bore")]
        check(all(o.InTolerance and max(abs(o.Deviation), abs(o.Form)) < 0.0005 and tuple(o.DeviationColor[:3]) not in
                  (dev.RED, dev.BLUE) for o in judged), "every point in tolerance, none red or blue: %s"
              % [(o.Label, o.Deviation, o.InTolerance) for o in judged if not o.InTolerance])
        check(all("InTolerance" not in o.PropertiesList and o.Characteristics == "" if "Characteristics" in o.PropertiesList
                  else "InTolerance" not in o.PropertiesList for o in s.points if o.Feature in ("front", "left")),
              "front and left carry no characteristic: no verdict on their points")
        r = rows(panel)
        check(sorted(r) == sorted(["height", "top flatness", "top parallelism", "bore diameter", "bore position",
                                   "bore roundness"]) and all(v.startswith("ok: ") and " µm" in v for v in r.values()),
              "the characteristics with µm in the panel: %s" % r)
        check(r.get("height", "").startswith("ok: 80.0000 mm, deviation ") and
              r.get("bore diameter", "").startswith("ok: 30.0000 mm"),
              "height 80, bore 30: %s" % r)
        check(pump(app, 2, lambda: s.control == "none") and "control free" in panel.state.text() and
              panel.measure_plan_button.isEnabled(), "messcap gave control back: %r" % panel.state.text())
        panel.measure_plan()
        check(pump(app, 20, lambda: s.control.startswith("messcap") and s.state in ("move", "retract")),
              "measuring again: %s" % panel.events.lines())
        mouse(panel.stop_button, "press")
        mouse(panel.stop_button, "release")
        check(panel.run is None and panel.events.text("inspect") == "inspection stopped: Stop pressed" and
              pump(app, 3, lambda: s.state == "idle" and s.control == "none") and panel.measure_plan_button.isEnabled(),
              "Stop stops the plan messcap measures, whether it is moving or between moves: %s" % panel.events.lines())
        check(not warnings, "no warnings: %s" % warnings)
        panel.toggle()
        FreeCAD.closeDocument(doc.Name)
    finally:
        messd.stop()


def plan_variant(name, bore_diameter):
    """The short plan without its alignment (the operator measures top and bore only; the part is
    placed where the plan says and turned 0.3° about the bore's axis, which moves neither)."""
    plan = json.load(open(SHORT_PLAN))
    del plan["alignment"]
    plan["features"] = [f for f in plan["features"] if f["name"] in ("top", "bore")]
    plan["features"][1]["diameter"] = bore_diameter
    plan["characteristics"] = [c for c in plan["characteristics"] if c.get("feature") in ("top", "bore")
                               and "datum" not in c]
    path = os.path.join(WORK, name)
    with open(path, "w") as f:
        json.dump(plan, f)
    return path


def hand_checks():
    mod, warnings, app = panel_module()
    messd = Messd()
    try:
        doc = FreeCAD.newDocument("inspectpoints")
        panel = mod.CapturePanel()
        check(connect_panel(panel, app, messd.port), "Connect: %s" % panel.events.lines())
        s = panel.session
        op = Operator(messd.port)
        op.start()
        pump(app, 90, lambda: not op.is_alive())
        check(op.error is None and pump(app, 2, lambda: len(s.points) == 7), "the operator's 7 points: %s" % op.error)
        op.close()
        top, bore = s.points[:3], s.points[3:]

        panel.choose_plan(plan_variant("top-bore.plan.json", 30))
        Gui.selected = []
        panel.inspect()
        check(len(warnings) == 1 and warnings[0].startswith("none of the 7 points has a feature of the plan: choose the "
                                                            "feature for new points") and
              panel.events.text("inspect").startswith("inspection failed: none of the 7 points"),
              "without features messcap cannot know what a point measures; the panel says how: %s" % warnings)
        for points, feature in ((top, "top"), (bore, "bore")):
            Gui.selected = points
            panel.feature_box.setCurrentText(feature)
            panel.assign()
        check([o.Label for o in s.points] == ["MeasPt%03d %s" % (i + 1, "top" if i < 3 else "bore") for i in range(7)],
              "Assign gives the selected points their feature: %s" % [o.Label for o in s.points])
        panel.feature_box.setCurrentText("top")
        mouse(panel.measure_button, "press")
        mouse(panel.measure_button, "release")
        check(pump(app, 3, lambda: len(s.points) == 8) and s.points[7].Feature == "top",
              "a new point gets the feature chosen for new points")
        Gui.selected = [s.points[7]]
        panel.feature_box.setCurrentText("(none)")
        panel.assign()
        check(s.points[7].Feature == "" and s.points[7].Label == "MeasPt008", "and (none) takes it away")

        Gui.selected = []
        panel.inspect()
        check(panel.events.text("inspect") == "messcap inspected 7 points (1 without a feature left out)",
              panel.events.text("inspect"))
        r = rows(panel)
        check(sorted(r) == ["bore diameter", "bore position", "bore roundness", "top flatness"] and
              all(v.startswith("ok: ") for v in r.values()), "the characteristics: %s" % r)
        diameter = float(r.get("bore diameter", "ok: 0 mm")[4:].split(" mm")[0])
        check(abs(diameter - 30) < 0.0005, "the bore probe-compensated along its fitted normals: Ø %.4f" % diameter)
        check(all(o.InTolerance and tuple(o.DeviationColor[:3]) not in (dev.RED, dev.BLUE) for o in s.points[:7])
              and "Deviation" not in s.points[7].PropertiesList, "all 7 in tolerance, the 8th untouched")

        panel.choose_plan(plan_variant("bore-too-large.plan.json", 30.1))
        panel.inspect()
        r = rows(panel)
        check(r.get("bore diameter", "").startswith(("OUT: 29.9999 mm, deviation -100.", "OUT: 30.0000 mm, deviation -100."))
              and r.get("top flatness", "").startswith("ok: "), "the bore drawn 0.1 too large: %s" % r)
        check(all(not o.InTolerance and abs(o.Deviation - 0.05) < 0.001 and tuple(o.DeviationColor[:3]) == dev.RED
                  for o in bore), "the bore's points are out and red (their surface 0.05 inside the drawn one): %s"
              % [(o.Deviation, tuple(o.DeviationColor)) for o in bore])
        check(all(o.InTolerance and tuple(o.DeviationColor[:3]) not in (dev.RED, dev.BLUE) for o in top),
              "the top's stay in tolerance")
        check(len(warnings) == 1, "no further warnings: %s" % warnings)
        panel.toggle()
        FreeCAD.closeDocument(doc.Name)
    finally:
        messd.stop()


finish("freecad inspect", live_checks, hand_checks)
