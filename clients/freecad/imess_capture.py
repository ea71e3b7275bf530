# IMESS live capture for FreeCAD, without the GUI: reads messd's protocol lines from a
# non-blocking socket, moves a probe marker with CurrCor and adds every MeasPt to the document
# at once. Fits (imess_fit), jogging (imess_jog) and deviations (imess_deviation) build on it.
"""IMESS capture logic for FreeCAD (testable under freecadcmd; the GUI macro only wires it)."""

import collections
import errno
import os
import shutil
import socket
import time

import FreeCAD
import Part

DEFAULT_HOST = "localhost"
DEFAULT_PORT = 1066
POINT_GROUP = "IMESS_Points"
MARKER = "IMESS_Probe"
MAX_LINE = 4096  # messd lines are short; a longer one is noise and is dropped


class CaptureError(Exception):
    """Connecting, reading, fitting or jogging failed; the message says what and why."""


def find_messcap():
    """messcap: $IMESS_MESSCAP, else on PATH, else build/bin/messcap of this source tree."""
    candidates = [os.environ.get("IMESS_MESSCAP"), shutil.which("messcap"),
                  os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "build", "bin", "messcap")]
    for c in candidates:
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return os.path.abspath(c)
    raise CaptureError("messcap not found: set IMESS_MESSCAP, put messcap on PATH, or build it "
                       "(scripts/run builds build/bin/messcap)")


def document_group(doc, name, label):
    """The group `name` of the document, made (labelled `label`) when it is not there yet."""
    group = doc.getObject(name)
    if group is None:
        group = doc.addObject("App::DocumentObjectGroup", name)
        group.Label = label
    return group


def xyz_text(points):
    """Points as 'x y z' lines at full precision: what messcap reads."""
    return "".join("%r %r %r\n" % (p.x, p.y, p.z) for p in points)


def parse_xyz(args):
    """'1.000 2.000 3.000' -> FreeCAD.Vector, or None when it is not three numbers."""
    parts = args.split()
    if len(parts) != 3:
        return None
    try:
        return FreeCAD.Vector(*(float(p) for p in parts))
    except ValueError:
        return None


class CaptureSession:
    """One link to messd feeding one document.

    poll() never blocks: it reads what the socket holds, handles every complete line and
    returns. Each MeasPt becomes a Part::Feature (a Part.Vertex) in the group IMESS_Points the
    moment its line is handled; nothing is buffered, so stopping at any time loses no point.
    """

    def __init__(self, doc, host=DEFAULT_HOST, port=DEFAULT_PORT, sock=None, marker_radius=1.0, clock=time.monotonic):
        self.doc = doc
        self.host, self.port = host, int(port)
        self.sock = sock
        self.marker_radius = marker_radius
        self.clock = clock
        self.buffer = b""
        self.position = None
        self.state = ""
        self.messages = []  # Warn / Fault / Err lines, newest last
        self.points = []    # the point objects this session created, in order
        self.closed_reason = ""
        self.pending = collections.deque()  # verbs sent and not yet answered (messd answers in order)
        self.last_sent = None               # clock() when the last line (or keep-alive) went out
        self.observers = []                 # observer(line, answered_verb) for every line received
        if self.sock is not None:
            self.sock.setblocking(False)

    # --- the link -------------------------------------------------------------------------
    def connect(self, timeout=3.0):
        try:
            self.sock = socket.create_connection((self.host, self.port), timeout=timeout)
        except OSError as e:
            raise CaptureError("no partner on %s:%d (%s) - is messd running?" % (self.host, self.port, e.strerror or e))
        self.sock.setblocking(False)
        self.closed_reason = ""
        self.pending.clear()
        self.send("Hello FreeCAD")

    def connected(self):
        return self.sock is not None

    def send(self, line):
        """Sends one line; "" is a keep-alive (no reply). A broken link closes the session."""
        if self.sock is None:
            raise CaptureError("not connected")
        line = line.rstrip("\n")
        data = (line + "\n").encode("ascii")
        self.sock.setblocking(True)
        try:
            self.sock.sendall(data)
        except OSError as e:
            self.close("link broken: %s" % e)
            raise CaptureError("link to messd broken while sending %r: %s" % (line, e))
        finally:
            if self.sock is not None:
                self.sock.setblocking(False)
        self.last_sent = self.clock()
        if line.strip():
            self.pending.append(line.split()[0])

    def close(self, reason="closed"):
        if self.sock is not None:
            try:
                self.sock.close()
            finally:
                self.sock = None
                self.closed_reason = reason
                self.pending.clear()

    def poll(self):
        """Handles every complete line available now; returns how many were handled."""
        if self.sock is None:
            return 0
        while True:
            try:
                chunk = self.sock.recv(65536)
            except (BlockingIOError, InterruptedError):
                break
            except OSError as e:
                if e.errno in (errno.EAGAIN, errno.EWOULDBLOCK):
                    break
                self.close("link broken: %s" % e)
                break
            if not chunk:
                self.close("closed by messd")
                break
            self.buffer += chunk
        handled = 0
        changed = False
        while b"\n" in self.buffer:
            raw, self.buffer = self.buffer.split(b"\n", 1)
            changed |= self.handle_line(raw.decode("ascii", "replace").rstrip("\r"))
            handled += 1
        if len(self.buffer) > MAX_LINE:
            self.buffer = b""
        if changed:
            self.doc.recompute()
        return handled

    # --- the protocol ---------------------------------------------------------------------
    def handle_line(self, line):
        """One protocol line; True when the document changed."""
        verb, _, args = line.partition(" ")
        answered = None  # the verb of our request an Ok / Err answers
        if verb in ("Ok", "Err") and self.pending:
            answered = self.pending.popleft()
        for observer in list(self.observers):
            observer(line, answered)
        if verb == "MeasPt":
            p = parse_xyz(args)
            if p is not None:
                self.add_point(p)
                return True
        elif verb == "CurrCor":
            p = parse_xyz(args)
            if p is not None:
                self.position = p
                return self.move_marker(p)
        elif verb == "State":
            self.state = args.strip()
        elif verb in ("Warn", "Fault", "Err", "Limit"):
            self.messages.append(line)
            del self.messages[:-20]
        return False

    # --- the document ---------------------------------------------------------------------
    def add_point(self, p):
        group = document_group(self.doc, POINT_GROUP, "IMESS points")
        obj = self.doc.addObject("Part::Feature", "MeasPt")
        obj.Shape = Part.Vertex(p)
        number = len(group.Group) + 1
        obj.Label = "MeasPt%03d" % number
        obj.addProperty("App::PropertyVector", "Measured", "IMESS", "the point as messd sent it (mm)")
        obj.Measured = p
        group.addObject(obj)
        self.points.append(obj)
        if FreeCAD.GuiUp:
            obj.ViewObject.PointSize = 6
            obj.ViewObject.PointColor = (0.0, 0.6, 0.0)
        return obj

    def move_marker(self, p):
        """Moves the probe marker (a placement change, no recompute); True when it was created."""
        marker = self.doc.getObject(MARKER)
        created = marker is None
        if created:
            marker = self.doc.addObject("Part::Sphere", MARKER)
            marker.Label = "IMESS probe"
            marker.Radius = self.marker_radius
            if FreeCAD.GuiUp:
                marker.ViewObject.ShapeColor = (1.0, 0.2, 0.0)
        marker.Placement = FreeCAD.Placement(p, FreeCAD.Rotation())
        return created
