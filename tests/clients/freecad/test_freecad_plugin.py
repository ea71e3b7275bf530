# Inside freecadcmd: the FreeCAD plugin against a real, simulated messd. A scripted operator
# measures the cube top (3 points) and the bore (3 points); the points must be in the document
# as they arrive, a plane and a circle (D 30 +- 0.005) are fitted through messcap, the document
# is saved, re-opened and checked. Then the jog logic on a fresh messd: hold +Z, let go, Measure
# here. argv: BIN_DIR SOURCE_DIR
import math
import os
import socket
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from plugin_test import BIN_DIR, MESSCAP, SOURCE_DIR, Gui, check, finish, macro_namespace  # noqa: E402

import FreeCAD  # noqa: E402
import imess_capture  # noqa: E402
import imess_fit  # noqa: E402
import imess_jog  # noqa: E402


class Operator(threading.Thread):
    """The measuring sequence of tests/e2e/test_worked_example.cpp, on its own connection."""

    def __init__(self, port):
        super().__init__(daemon=True)
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=20)
        self.buf = b""
        self.points = []  # (kind, x, y, z) as the operator saw them
        self.error = None

    def line(self):
        while b"\n" not in self.buf:
            chunk = self.sock.recv(4096)
            if not chunk:
                raise RuntimeError("messd closed the operator's connection")
            self.buf += chunk
        raw, self.buf = self.buf.split(b"\n", 1)
        return raw.decode()

    def until(self, prefix):
        while True:
            line = self.line()
            if line.startswith(prefix):
                return line
            if line.startswith(("Err", "Fault", "Warn")):
                raise RuntimeError("operator got %r while waiting for %r" % (line, prefix))

    def request(self, command):
        self.sock.sendall((command + "\n").encode())
        reply = self.until("Ok " + command.split()[0])
        return reply

    def go_to(self, x, y, z):
        self.request("GoTo %.3f %.3f %.3f" % (x, y, z))
        self.until("State idle")

    def touch(self, kind, vx, vy, vz):
        self.request("StartMv %.3f %.3f %.3f" % (vx, vy, vz))
        p = [float(v) for v in self.until("MeasPt ").split()[1:]]
        self.until("State idle")
        self.points.append((kind, *p))

    def run(self):
        try:
            for x, y in ((420, 325), (500, 320), (430, 385)):  # top, clear of bore and fillet
                self.go_to(x, y, 100)
                self.touch("top", 0, 0, -50)
                self.go_to(x, y, 100)
            self.go_to(460, 350, 100)
            self.go_to(460, 350, 40)
            for deg in (10, 130, 250):
                a = math.radians(deg)
                self.touch("bore", 50 * math.cos(a), 50 * math.sin(a), 0)
                self.go_to(460, 350, 40)
            self.go_to(460, 350, 100)
        except Exception as e:  # noqa: BLE001 - reported by the main thread
            self.error = "%s: %s" % (type(e).__name__, e)


def start_messd():
    config = os.path.join(SOURCE_DIR, "tests", "e2e", "fast-cmm.json")
    journal = tempfile.mkdtemp(prefix="imess-freecad-journal-")  # never the shared default
    proc = subprocess.Popen([os.path.join(BIN_DIR, "messd"), "--port", "0", "--listen", "127.0.0.1", "--no-rt",
                             "--config", config, "--journal", journal],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    first = proc.stdout.readline()  # "messd: OK, listening on 127.0.0.1:PORT"
    if not first.startswith("messd: OK"):
        proc.kill()
        raise RuntimeError("messd did not start: %r" % first)
    return proc, int(first.rsplit(":", 1)[1])


def protocol_checks():
    """Line handling on a socket pair: points at once, split lines, noise, a closing link."""
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
    check(s.messages == ["Warn TipNotFree x"] and s.state == "idle", "Warn and State are kept")
    daemon.close()
    s.poll()
    check(not s.connected() and s.closed_reason == "closed by messd", "a closed link is noticed")
    try:
        imess_fit.run_fit("circle", [FreeCAD.Vector(i, 0, 0) for i in range(3)], MESSCAP)
        check(False, "a fit of collinear points must fail")
    except imess_capture.CaptureError as e:
        check("collinear" in str(e), "the failed fit says why: %s" % e)
    FreeCAD.closeDocument(doc.Name)


def panel_checks():
    """The GUI macro's wiring, on an offscreen Qt: Connect, timer ticks, the Circle button."""
    ns, warnings, app = macro_namespace()
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(1)
    doc = FreeCAD.newDocument("panel")
    panel = ns["CapturePanel"]()
    panel.host.setText("127.0.0.1")
    panel.port.setValue(server.getsockname()[1])
    server.settimeout(5)
    panel.toggle()
    try:
        conn, _ = server.accept()
    except socket.timeout:
        check(False, "Connect did not connect: %s" % panel.status.text())
        return
    check(panel.session is not None and panel.session.connected() and panel.timer.isActive(),
          "Connect connects and starts the poll timer")
    lines = ["CurrCor 1.000 2.000 3.000"] + ["MeasPt %.3f %.3f 5.000" % (10 * math.cos(a), 10 * math.sin(a))
                                              for a in (0.0, 2.0, 4.0)]
    conn.sendall(("\n".join(lines) + "\n").encode())
    end = time.time() + 5
    while time.time() < end and len(panel.session.points) < 3:
        app.processEvents()  # the QTimer fires tick()
        time.sleep(0.01)
    check(len(panel.session.points) == 3, "the panel's timer brought in the points: %d" % len(panel.session.points))
    check(panel.position.text() == "1.000  2.000  3.000", "position shown: %r" % panel.position.text())
    Gui.selected = list(panel.session.points)
    panel.fit("circle")
    circles = [o for o in doc.Objects if getattr(o, "FitType", "") == "circle"]
    check(not warnings and len(circles) == 1 and abs(circles[0].Diameter - 20) < 1e-3,
          "the Circle button made a D20 circle (warnings: %s)" % warnings)
    Gui.selected = list(panel.session.points[:2])
    panel.fit("sphere")
    check(len(warnings) == 1 and "too_few_points" in warnings[0], "a failed fit is shown: %s" % warnings)
    panel.toggle()
    check(not panel.session.connected() and not panel.timer.isActive(), "Disconnect stops the timer")
    conn.close()
    server.close()
    FreeCAD.closeDocument(doc.Name)


def capture_checks(workdir):
    messd, port = start_messd()
    try:
        doc = FreeCAD.newDocument("capture")
        session = imess_capture.CaptureSession(doc, "127.0.0.1", port)
        session.connect()
        op = Operator(port)
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
        check(len(op.points) == 6, "6 points measured, got %d" % len(op.points))
        check(len(session.points) == len(op.points), "every point is in the document (%d of %d)"
              % (len(session.points), len(op.points)))
        check(len(set(seen_counts)) >= 4, "points appeared one by one while measuring: %s" % sorted(set(seen_counts)))
        for obj, (kind, x, y, z) in zip(session.points, op.points):
            v = obj.Shape.Vertexes[0].Point
            check((v - FreeCAD.Vector(x, y, z)).Length < 1e-9, "%s is %s, messd said %s" % (obj.Label, v, (x, y, z)))
        check(doc.getObject(imess_capture.MARKER) is not None and session.position is not None and
              (doc.getObject(imess_capture.MARKER).Placement.Base - session.position).Length < 1e-9,
              "the probe marker sits at the last CurrCor")
        session.close()

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
        expected = [tuple(p[1:]) for p in op.points]
        FreeCAD.closeDocument(doc.Name)

        doc = FreeCAD.openDocument(path)
        group = doc.getObject(imess_capture.POINT_GROUP)
        reopened = [tuple(o.Shape.Vertexes[0].Point) for o in group.Group]
        check(reopened == expected, "re-opened points %s, expected %s" % (reopened, expected))
        circles = [o for o in doc.Objects if getattr(o, "FitType", "") == "circle"]
        check(len(circles) == 1, "one fitted circle in the re-opened document")
        if circles:
            c = circles[0]
            check(abs(c.Diameter - 30.0) <= 0.005 and c.PointCount == 3 and c.RMS >= 0, "re-opened circle values")
            check(abs(c.Shape.Edges[0].Curve.Radius * 2 - c.Diameter) < 1e-9, "re-opened circle geometry")
            check(len(c.FitPoints) == 3, "the circle links its 3 points")
        check(any(getattr(o, "FitType", "") == "plane" for o in doc.Objects), "the plane is in the re-opened document")
        FreeCAD.closeDocument(doc.Name)
    finally:
        messd.terminate()
        messd.wait(10)


def jog_checks():
    """The jog buttons' logic on a real messd: hold +Z, let go, Measure here."""
    messd, port = start_messd()
    try:
        doc = FreeCAD.newDocument("jog")
        session = imess_capture.CaptureSession(doc, "127.0.0.1", port)
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
        check(session.state == "idle" and session.position.z > start.z + 0.5 and not session.messages,
              "held +Z moved up, letting go stopped it: %s -> %s, %s %s" % (start, session.position, session.state,
                                                                            session.messages))
        stopped_at = session.position
        jog.measure_here()
        run(3, lambda: len(session.points) == 1)
        check(len(session.points) == 1 and (session.points[0].Measured - stopped_at).Length < 0.001,
              "Measure here put the standing position %s into the document: %s" % (stopped_at, [p.Measured for p in session.points]))
        session.close()
        FreeCAD.closeDocument(doc.Name)
    finally:
        messd.terminate()
        messd.wait(10)


def capture_in_tempdir():
    with tempfile.TemporaryDirectory(prefix="imess-freecad-") as d:
        capture_checks(d)


finish("freecad plugin", protocol_checks, panel_checks, capture_in_tempdir, jog_checks)
