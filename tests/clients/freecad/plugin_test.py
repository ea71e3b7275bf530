# What the FreeCAD plugin tests share (they run inside freecadcmd): argv (BIN_DIR SOURCE_DIR),
# the plugin on sys.path, check(), a real messd on a free loopback port, a scripted operator on
# its own connection, the panel module with stand-ins for what freecadcmd lacks (FreeCADGui's
# selection, modal dialogs), real Qt mouse events, and the exit status.
import json
import os
import socket
import subprocess
import sys
import tempfile
import threading
import time
import traceback

BIN_DIR, SOURCE_DIR = sys.argv[1], sys.argv[2]
PLUGIN_DIR = os.path.join(SOURCE_DIR, "clients", "freecad")
sys.path.insert(0, PLUGIN_DIR)
MESSCAP = os.path.join(BIN_DIR, "messcap")
os.environ["IMESS_MESSCAP"] = MESSCAP  # the plugin's way to be told which messcap to run
SHORT_PLAN = os.path.join(SOURCE_DIR, "tests", "clients", "freecad", "cube-short.plan.json")
failures = []


def check(condition, text):
    if not condition:
        failures.append(text)
        print("FAIL " + text)
    return condition


class Messd:
    """A real messd (the simulated CMM with brisk speeds, tests/e2e/fast-cmm.json) on a free
    loopback port, its journal and frames in a directory of its own. Its clock runs at that
    file's sim.speed (4: measuring in a quarter of the time); a test that reads speeds off the
    wall clock (a jog's mm/s) gives real_speed=True for the same machine at 1; scanning=True gives
    it the measuring probe of config/sim-servo-card-scanning.json."""

    def __init__(self, real_speed=False, scanning=False):
        self.dir = tempfile.mkdtemp(prefix="imess-freecad-messd-")
        config = os.path.join(SOURCE_DIR, "tests", "e2e", "fast-cmm.json")
        if real_speed or scanning:
            with open(config) as f:
                settings = json.load(f)
            if real_speed:
                settings["sim"]["speed"] = 1
            if scanning:
                with open(os.path.join(SOURCE_DIR, "config", "sim-servo-card-scanning.json")) as f:
                    settings["sim"]["probe"] = json.load(f)["sim"]["probe"]
            config = os.path.join(self.dir, "fast-cmm-derived.json")
            with open(config, "w") as f:
                json.dump(settings, f)
        self.proc = subprocess.Popen([os.path.join(BIN_DIR, "messd"), "--port", "0", "--listen", "127.0.0.1", "--no-rt",
                                      "--config", config, "--journal", self.dir], cwd=self.dir,
                                     stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        first = self.proc.stdout.readline()  # "messd: OK, listening on 127.0.0.1:PORT"
        if not first.startswith("messd: OK"):
            self.proc.kill()
            raise RuntimeError("messd did not start: %r" % first)
        self.port = int(first.rsplit(":", 1)[1])

    def stop(self):
        if self.proc.poll() is None:
            self.proc.terminate()
            self.proc.wait(10)


class Operator(threading.Thread):
    """Another client on its own connection: telnet, messjog or a script at the machine."""

    def __init__(self, port, script=None):
        super().__init__(daemon=True)
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=20)
        self.buf = b""
        self.points = []  # (kind, x, y, z) as the operator saw them
        self.error = None
        self.script = script

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
        return self.until("Ok " + command.split()[0])

    def go_to(self, x, y, z):
        self.request("GoTo %.3f %.3f %.3f" % (x, y, z))
        self.until("State idle")

    def touch(self, kind, vx, vy, vz):
        self.request("StartMv %.3f %.3f %.3f" % (vx, vy, vz))
        p = [float(v) for v in self.until("MeasPt ").split()[1:]]
        self.until("State idle")
        self.points.append((kind, *p))

    def top_and_bore(self):
        """Three points on the cube's top (clear of bore and fillet), four in the Ø 30 bore."""
        import math
        for x, y in ((420, 325), (500, 320), (430, 385)):
            self.go_to(x, y, 100)
            self.touch("top", 0, 0, -50)
            self.go_to(x, y, 100)
        self.go_to(460, 350, 100)
        self.go_to(460, 350, 40)
        for deg in (10, 100, 190, 280):
            a = math.radians(deg)
            self.touch("bore", 50 * math.cos(a), 50 * math.sin(a), 0)
            self.go_to(460, 350, 40)
        self.go_to(460, 350, 100)

    def run(self):
        try:
            (self.script or self.top_and_bore)()
        except Exception as e:  # noqa: BLE001 - reported by the main thread
            self.error = "%s: %s" % (type(e).__name__, e)

    def close(self):
        self.sock.close()


class Gui:
    """freecadcmd's FreeCADGui lacks the selection and updateGui the panel uses."""

    selected = []
    app = None

    class Selection:
        @staticmethod
        def getSelection():
            return list(Gui.selected)

    @staticmethod
    def updateGui():
        Gui.app.processEvents()


def panel_module():
    """imess_panel on an offscreen Qt with FreeCADGui replaced by Gui; QMessageBox.warning records
    into the returned list instead of waiting for a click. Returns (module, warnings, app)."""
    from PySide import QtGui

    app = QtGui.QApplication.instance() or QtGui.QApplication([])
    Gui.app = app
    import imess_panel

    imess_panel.FreeCADGui = Gui
    warnings = []
    QtGui.QMessageBox.warning = staticmethod(lambda parent, title, text: warnings.append(text))
    return imess_panel, warnings, app


def pump(app, seconds, until=lambda: False):
    """Runs Qt's events (the panel's timer) for up to `seconds`, or until until() holds."""
    end = time.time() + seconds
    while time.time() < end and not until():
        app.processEvents()
        time.sleep(0.005)
    return until()


def mouse(button, kind, inside=True):
    """A left-button mouse event on a Qt button, at its centre or well outside it."""
    from PySide import QtCore, QtGui

    pos = QtCore.QPointF(button.rect().center()) if inside else QtCore.QPointF(-50, -50)
    event_type = {"press": QtCore.QEvent.MouseButtonPress, "release": QtCore.QEvent.MouseButtonRelease,
                  "move": QtCore.QEvent.MouseMove}[kind]
    buttons = QtCore.Qt.NoButton if kind == "release" else QtCore.Qt.LeftButton
    which = QtCore.Qt.NoButton if kind == "move" else QtCore.Qt.LeftButton
    QtGui.QApplication.sendEvent(button, QtGui.QMouseEvent(event_type, pos, which, buttons, QtCore.Qt.NoModifier))


def connect_panel(panel, app, port):
    """Connect on the panel to messd's port; True once the panel has its first position."""
    panel.host.setText("127.0.0.1")
    panel.port.setValue(port)
    panel.toggle()
    return pump(app, 5, lambda: panel.session.position is not None and panel.session.control != "")


def finish(name, *steps):
    """Runs the steps, prints the summary and exits 1 on any failure or exception."""
    started = time.time()
    try:
        for step in steps:
            step()
    except Exception:  # noqa: BLE001 - any exception fails the test with its traceback
        traceback.print_exc()
        failures.append("exception")
    print("%s: %d failures, %.1f s" % (name, len(failures), time.time() - started))
    sys.stdout.flush()
    os._exit(1 if failures else 0)
