# Inside freecadcmd: the FreeCAD plugin against a real, simulated messd. A scripted operator
# measures the cube top (3 points) and the bore (4 points); the points must be in the document
# as they arrive, with their hits' numbers, approaches and tip radius; a plane and a circle
# (D 30 +- 0.005) are fitted through messcap, the document is saved, re-opened and checked. The
# panel does the same through its timer and its Circle button, its results shown in µm. Then the
# jog logic on a fresh messd: hold +Z, let go, Measure here. argv: BIN_DIR SOURCE_DIR
import os
import re
import socket
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from plugin_test import (MESSCAP, Gui, Messd, Operator, check, connect_panel, finish, panel_module,  # noqa: E402
                         pump)

import FreeCAD  # noqa: E402
import imess_capture  # noqa: E402
import imess_fit  # noqa: E402
import imess_jog  # noqa: E402


def protocol_checks():
    """Line handling on a socket pair (lines no messd sends on purpose): points at once, split
    lines, noise, a Hit paired with its MeasPt, Status and Control read, a closing link."""
    doc = FreeCAD.newDocument("protocol")
    ours, daemon = socket.socketpair()
    s = imess_capture.CaptureSession(doc, sock=ours)
    daemon.sendall(b"CurrCor 1.000 2.000 3.000\nMeasPt 10.250 0.000 -7.000\n")
    s.poll()
    check(len(s.points) == 1, "a MeasPt is in the document after one poll")
    check(doc.getObject(imess_capture.MARKER).Placement.Base == FreeCAD.Vector(1, 2, 3), "marker follows CurrCor")
    daemon.sendall(b"MeasPt 1.0")
    s.poll()
    check(len(s.points) == 1, "half a line is not a point")
    daemon.sendall(b"00 2.000 3.000\nMeasPt 1 2\nWarn TipNotFree x\nState idle\n")
    s.poll()
    check(len(s.points) == 2 and s.points[1].Shape.Vertexes[0].Point == FreeCAD.Vector(1, 2, 3),
          "a split line is one point; a malformed MeasPt is ignored")
    check(s.events.text("messd") == "Warn TipNotFree x" and s.state == "idle", "Warn goes to the events, State is kept")
    daemon.sendall(b"Hit 17 0 5.0004 6.0000 7.0000 0.000000 0.000000 -1.000000 1.5000 12.000000\nMeasPt 5.000 6.000 7.000\n"
                   b"Hit 18 0 9.0000 9.0000 9.0000 0.000000 0.000000 -1.000000 1.5000 13.000000\nMeasPt 1.000 1.000 1.000\n")
    s.poll()
    hit, plain = s.points[2], s.points[3]
    check(hit.Measured == FreeCAD.Vector(5.0004, 6, 7) and hit.HitNumber == 17 and hit.Approach == FreeCAD.Vector(0, 0, -1)
          and hit.TipRadius == 1.5 and s.tip_radius == 1.5,
          "a MeasPt after its Hit is the hit's point (4 decimals) with its number, approach and tip radius")
    check(plain.Measured == FreeCAD.Vector(1, 1, 1) and "HitNumber" not in plain.PropertiesList,
          "a MeasPt that is not the Hit before it stays a plain point")
    check(abs(doc.getObject(imess_capture.MARKER).Shape.BoundBox.XLength - 3.0) < 1e-6,
          "the probe marker's ball has the tip radius messd applies")
    daemon.sendall(b"Ok Status State idle Pos 1 2 3 Loops closed Tip free Limits Xneg Homed no Referenced yes "
                   b"TipRadius 2.500 SpeedLevel 1.000 Clients 2 Control messjog@127.0.0.1\n")
    s.pending.append("Status")
    s.poll()
    check(s.control == "messjog 127.0.0.1" and s.tip_radius == 2.5 and "messjog" in s.events.text("control"),
          "Status: control and tip radius (%r, %s)" % (s.control, s.tip_radius))
    daemon.sendall(("Control %s 127.0.0.1\n" % s.name).encode())
    s.poll()
    check(s.holds_control() and s.events.text("control") == "this panel controls the machine", s.events.text("control"))
    daemon.close()
    s.poll()
    check(not s.connected() and s.closed_reason == "closed by messd" and "link ended" in s.events.text("link"),
          "a closed link is noticed")
    try:
        imess_fit.run_fit("circle", [FreeCAD.Vector(i, 0, 0) for i in range(3)], MESSCAP)
        check(False, "a fit of collinear points must fail")
    except imess_capture.CaptureError as e:
        check("collinear" in str(e), "the failed fit says why: %s" % e)
    FreeCAD.closeDocument(doc.Name)


def panel_checks():
    """The panel on a real messd: Connect, the timer brings the operator's points, the Circle
    button fits the bore, the result is in the panel's list with µm; Disconnect."""
    mod, warnings, app = panel_module()
    messd = Messd()
    try:
        doc = FreeCAD.newDocument("panel")
        panel = mod.CapturePanel()
        check(connect_panel(panel, app, messd.port), "Connect connects: %s" % panel.events.lines())
        check(panel.session.connected() and panel.timer.isActive(), "Connect connects and starts the poll timer")
        check(panel.position.text().split() == ["X", "430.000", "Y", "330.000", "Z", "100.000"],
              "position shown: %r" % panel.position.text())
        check(panel.state.text().split()[0] in ("free", "idle") and "control free" in panel.state.text(),
              "state line: %r" % panel.state.text())
        op = Operator(messd.port)
        op.start()
        pump(app, 90, lambda: not op.is_alive())
        pump(app, 2, lambda: len(panel.session.points) == len(op.points))
        check(op.error is None and len(panel.session.points) == 7, "the panel's timer brought in the points: %d (%s)"
              % (len(panel.session.points), op.error))
        check("7 points" in panel.state.text(), "the state line counts them: %r" % panel.state.text())
        bore = [o for o, p in zip(panel.session.points, op.points) if p[0] == "bore"]
        Gui.selected = bore
        panel.fit("circle")
        circles = [o for o in doc.Objects if getattr(o, "FitType", "") == "circle"]
        check(not warnings and len(circles) == 1 and abs(circles[0].Diameter - 30) < 0.005,
              "the Circle button made the Ø 30 circle (warnings: %s)" % warnings)
        name, value = panel.results()[0] if panel.results() else ("", "")
        check(re.fullmatch(r"circle D(29\.99|30\.00)\d\d", name) and
              re.fullmatch(r"Ø (29\.99|30\.00)\d\d mm, form \d+\.\d µm, rms \d+\.\d µm, 4 points", value),
              "the result in the panel, µm: %r %r" % (name, value))
        form_um = float(value.split("form ")[1].split(" µm")[0])
        check(abs(form_um - (circles[0].FormMax - circles[0].FormMin) * 1000) < 0.051,
              "form shown to 0.1 µm: %s, fitted %.6f mm" % (form_um, circles[0].FormMax - circles[0].FormMin))
        check(panel.events.text("fit") == "%s: %s" % (name, value), "and in the events: %s" % panel.events.text("fit"))
        Gui.selected = bore[:2]
        panel.fit("sphere")
        check(len(warnings) == 1 and "too_few_points" in warnings[0] and "fit sphere failed" in panel.events.text("fit"),
              "a failed fit is shown: %s" % warnings)
        panel.toggle()
        check(not panel.session.connected() and not panel.timer.isActive() and "disconnected" in panel.events.text("link"),
              "Disconnect stops the timer")
        op.close()
        FreeCAD.closeDocument(doc.Name)
    finally:
        messd.stop()


def capture_checks(workdir):
    messd = Messd()
    try:
        doc = FreeCAD.newDocument("capture")
        session = imess_capture.CaptureSession(doc, "127.0.0.1", messd.port)
        session.connect()
        op = Operator(messd.port)
        op.start()
        deadline = time.time() + 90
        seen_counts = []
        while op.is_alive() and time.time() < deadline:
            session.poll()
            seen_counts.append(len(session.points))
            time.sleep(0.01)
        end = time.time() + 2
        while time.time() < end and len(session.points) < len(op.points):
            session.poll()
            time.sleep(0.01)
        check(op.error is None, "operator: %s" % op.error)
        check(len(op.points) == 7, "7 points measured, got %d" % len(op.points))
        check(len(session.points) == len(op.points), "every point is in the document (%d of %d)"
              % (len(session.points), len(op.points)))
        check(len(set(seen_counts)) >= 4, "points appeared one by one while measuring: %s" % sorted(set(seen_counts)))
        for obj, (kind, x, y, z) in zip(session.points, op.points):
            v = obj.Shape.Vertexes[0].Point
            check((v - FreeCAD.Vector(x, y, z)).Length < 0.0006 and v == obj.Measured and obj.HitNumber > 0 and
                  abs(obj.Approach.Length - 1) < 1e-6 and obj.TipRadius == 2.0,
                  "%s is %s (hit %d), messd said %s" % (obj.Label, v, getattr(obj, "HitNumber", 0), (x, y, z)))
        check([o.HitNumber for o in session.points] == list(range(1, 8)), "the hits' numbers in the journal")
        check(doc.getObject(imess_capture.MARKER) is not None and session.position is not None and
              (doc.getObject(imess_capture.MARKER).Placement.Base - session.position).Length < 1e-9,
              "the probe marker sits at the last CurrCor")
        session.close()
        op.close()

        top = [o for o, p in zip(session.points, op.points) if p[0] == "top"]
        bore = [o for o, p in zip(session.points, op.points) if p[0] == "bore"]
        plane = imess_fit.fit_feature(doc, "plane", top, MESSCAP)
        circle = imess_fit.fit_feature(doc, "circle", bore, MESSCAP)
        check(abs(circle.Diameter - 30.0) <= 0.005, "bore diameter %.6f, expected 30 +- 0.005" % circle.Diameter)
        check(abs(circle.Center.x - 460) < 0.5 and abs(circle.Center.y - 350) < 0.5, "bore centre %s" % circle.Center)
        check(abs(abs(plane.Normal.z) - 1) < 1e-6 and abs(plane.FitPoint.z - 80) <= 0.005,
              "top plane: normal %s, point %s" % (plane.Normal, plane.FitPoint))
        check(circle.Shape.Edges[0].Curve.TypeId == "Part::GeomCircle" and
              abs(circle.Shape.Edges[0].Curve.Radius - circle.Diameter / 2) < 1e-9, "the circle is a circle edge")
        check(len(plane.Shape.Faces) == 1, "the plane is a face")

        path = os.path.join(workdir, "capture.FCStd")
        doc.saveAs(path)
        expected = [(o.Measured.x, o.Measured.y, o.Measured.z) for o in session.points]
        FreeCAD.closeDocument(doc.Name)

        doc = FreeCAD.openDocument(path)
        group = doc.getObject(imess_capture.POINT_GROUP)
        reopened = [tuple(o.Shape.Vertexes[0].Point) for o in group.Group]
        check(reopened == expected, "re-opened points %s, expected %s" % (reopened, expected))
        check([o.HitNumber for o in group.Group] == list(range(1, 8)), "with their hit numbers")
        circles = [o for o in doc.Objects if getattr(o, "FitType", "") == "circle"]
        check(len(circles) == 1, "one fitted circle in the re-opened document")
        if circles:
            c = circles[0]
            check(abs(c.Diameter - 30.0) <= 0.005 and c.PointCount == 4 and c.RMS >= 0 and " µm" in c.Result,
                  "re-opened circle values: %s" % c.Result)
            check(abs(c.Shape.Edges[0].Curve.Radius * 2 - c.Diameter) < 1e-9, "re-opened circle geometry")
            check(len(c.FitPoints) == 4, "the circle links its 4 points")
        check(any(getattr(o, "FitType", "") == "plane" for o in doc.Objects), "the plane is in the re-opened document")
        FreeCAD.closeDocument(doc.Name)
    finally:
        messd.stop()


def jog_checks():
    """The jog buttons' logic on a real messd: hold +Z, let go, Measure here."""
    messd = Messd()
    try:
        doc = FreeCAD.newDocument("jog")
        session = imess_capture.CaptureSession(doc, "127.0.0.1", messd.port)
        session.connect()
        jog = imess_jog.JogControl(session)

        def run(seconds, until=lambda: False):
            end = time.time() + seconds
            while time.time() < end and not until():
                session.poll()
                jog.tick()
                time.sleep(0.01)

        run(2, lambda: session.position is not None)
        start = session.position
        jog.press("+Z")
        run(2, lambda: session.position is not None and session.position.z > start.z + 0.5)
        jog.release("+Z")
        run(5, lambda: session.state == "idle")
        run(0.5)  # CurrCor comes at most ReportHz (10) times a second: the last one after the stop
        check(session.state == "idle" and session.position.z > start.z + 0.5 and session.events.text("messd") is None,
              "held +Z moved up, letting go stopped it: %s -> %s, %s %s" % (start, session.position, session.state,
                                                                            session.events.lines()))
        check(session.events.text("jog") == "jog +Z ended", "the jog's event says it ended: %s" % session.events.text("jog"))
        stopped_at = session.position
        jog.measure_here()
        run(3, lambda: len(session.points) == 1)
        check(len(session.points) == 1 and (session.points[0].Measured - stopped_at).Length < 0.001,
              "Measure here put the standing position %s into the document: %s" % (stopped_at, [p.Measured for p in session.points]))
        session.close()
        FreeCAD.closeDocument(doc.Name)
    finally:
        messd.stop()


def capture_in_tempdir():
    with tempfile.TemporaryDirectory(prefix="imess-freecad-") as d:
        capture_checks(d)


finish("freecad plugin", protocol_checks, panel_checks, capture_in_tempdir, jog_checks)
