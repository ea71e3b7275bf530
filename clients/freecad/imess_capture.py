# IMESS live capture for FreeCAD, without the GUI: reads messd's protocol lines from a
# non-blocking socket, moves the probe marker with CurrCor and adds every measured point to the
# document at once (with its hit's number, approach and tip radius), and a scan's points to its
# point cloud once per poll (imess_scan). Fits (imess_fit), jogging (imess_jog), plans
# (imess_inspect) and deviations (imess_deviation) build on it.
"""IMESS capture logic for FreeCAD (testable under freecadcmd; the panel only wires it)."""

import collections
import errno
import os
import shutil
import socket
import time

import FreeCAD
import Part

from imess_events import EventLog
from imess_scan import ScanClouds, parse_scan

DEFAULT_HOST = "localhost"
DEFAULT_PORT = 1066
POINT_GROUP = "IMESS_Points"
MARKER = "IMESS_Probe"
MAX_LINE = 4096  # messd lines are short; a longer one is noise and is dropped
POINT_SIZE = 9  # pixels: a point stays visible whatever the zoom
POINT_COLOUR = (0.0, 0.55, 0.0)
MARKER_COLOUR = (1.0, 0.35, 0.0)
DEFAULT_TIP_RADIUS = 2.0  # mm, until messd says (Status, Hit, Qualified)
HIT_MATCH_MM = 1e-3  # a MeasPt within this of the Hit just before it is that hit's point
OWNER_WARNINGS = ("Warn WatchExpired", "Warn ControlTaken")  # shown by the jog (imess_jog), whose motion they stopped


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
    """Points as 'x y z' lines at full precision: what messcap fit reads."""
    return "".join("%r %r %r\n" % (p.x, p.y, p.z) for p in points)


def numbers(words, count):
    """`count` floats from the words, or None when they are not that many numbers."""
    if len(words) < count:
        return None
    try:
        return [float(w) for w in words[:count]]
    except ValueError:
        return None


def parse_xyz(args):
    """'1.000 2.000 3.000' -> FreeCAD.Vector, or None when it is not three numbers."""
    words = args.split()
    v = numbers(words, 3) if len(words) == 3 else None
    return FreeCAD.Vector(*v) if v else None


def parse_hit(args):
    """'seq id x y z i j k r t' -> {"seq", "point", "approach", "radius"}, or None."""
    words = args.split()
    v = numbers(words, 10) if len(words) == 10 else None
    if v is None or v[0] != int(v[0]):
        return None
    return {"seq": int(v[0]), "point": FreeCAD.Vector(*v[2:5]), "approach": FreeCAD.Vector(*v[5:8]), "radius": v[8]}


STATUS_NAMES = ("State", "Pos", "Loops", "Tip", "Limits", "Homed", "Referenced", "TipRadius", "SpeedLevel",
                "Clients", "Control")


def status_fields(args):
    """'Status State idle Pos 1 2 3 … TipRadius 2.000 … Control none' -> {name: [words]}."""
    fields, name = {}, None
    for word in args.split()[1:]:
        if word in STATUS_NAMES and name != "Control":
            name = word
            fields[name] = []
        elif name is not None:
            fields[name].append(word)
    return fields


def probe_shape(radius):
    """The probe marker: the ball (the tip radius) on a stylus shaft pointing up, so it is seen at
    the scale of a part. Placed at the ball centre."""
    r = max(radius, 0.5)
    ball = Part.makeSphere(r)
    shaft = Part.makeCylinder(0.4 * r, 12 * r, FreeCAD.Vector(0, 0, 0.8 * r))
    return Part.makeCompound([ball, shaft])


class CaptureSession:
    """One link to messd feeding one document.

    poll() never blocks: it reads what the socket holds, handles every complete line and
    returns. Each MeasPt becomes a Part::Feature (a Part.Vertex) in the group IMESS_Points the
    moment its line is handled; nothing is buffered, so stopping at any time loses no point.
    What happens goes to `events` (an EventLog) with its time.
    """

    def __init__(self, doc, host=DEFAULT_HOST, port=DEFAULT_PORT, sock=None, clock=time.monotonic, events=None):
        self.doc = doc
        self.host, self.port = host, int(port)
        self.sock = sock
        self.clock = clock
        self.events = events if events is not None else EventLog()
        self.name = "FreeCAD-%d" % os.getpid()  # the Hello name: how Control lines say it is us
        self.buffer = b""
        self.position = None
        self.state = ""
        self.control = ""   # "" unknown, "none", or "name host" of the client in control
        self.tip_radius = DEFAULT_TIP_RADIUS
        self.feature = ""   # the plan feature new points are given ("" none)
        self.points = []    # the point objects this session created, in order
        self.last_hit = None  # the Hit line just before a MeasPt
        self.closed_reason = ""
        self.pending = collections.deque()  # verbs sent and not yet answered (messd answers in order)
        self.last_sent = None               # clock() when the last line (or keep-alive) went out
        self.observers = []                 # observer(line, answered_verb) for every line received
        self.scans = ScanClouds(doc, self.events)  # the scans' point clouds
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
        self.send("Hello %s" % self.name)
        self.send("Status")  # the state, the tip radius and who holds control, at once
        self.events.post("link", "connected to messd at %s:%d" % (self.host, self.port))

    def connected(self):
        return self.sock is not None

    def holds_control(self):
        return self.control.split(" ")[0] == self.name

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
                self.control = ""
                try:
                    if self.scans.close("link ended: %s" % reason):
                        self.doc.recompute()
                except Exception:  # noqa: BLE001 - the document was closed under the session: nothing to keep
                    pass
                self.events.post("link", "link ended (%s); %d points captured%s" % (
                    reason, len(self.points), ", %d scan points" % self.scans.points if self.scans.points else ""))

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
        changed |= self.scans.flush()  # the poll's scan points at once: one recompute, not one per point
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
            hit, self.last_hit = self.last_hit, None
            if p is not None:
                self.add_point(p, hit if hit is not None and (hit["point"] - p).Length <= HIT_MATCH_MM else None)
                return True
        elif verb == "Hit":
            self.last_hit = parse_hit(args)
            if self.last_hit is not None and self.last_hit["radius"] > 0:
                self.set_tip_radius(self.last_hit["radius"])
        elif verb == "Scan":
            scan = parse_scan(args)
            if scan is not None:
                self.scans.add(scan)
        elif verb in ("Done", "Failed"):
            words = args.split()
            if words and words[0].isdigit():
                self.scans.end(int(words[0]), "done" if verb == "Done" else "failed: " + " ".join(words[1:2]))
        elif verb == "CurrCor":
            p = parse_xyz(args)
            if p is not None:
                self.position = p
                return self.move_marker(p)
        elif verb == "State":
            if self.state == "fault" and args.strip() != "fault":
                self.events.clear("messd")  # the fault was reset
            self.state = args.strip()
        elif verb == "Control":
            self.set_control(args.strip())
        elif verb == "Qualified":
            words = args.split()
            if len(words) >= 2 and words[0] == "TipRadius" and numbers(words[1:], 1):
                self.set_tip_radius(float(words[1]))
        elif verb in ("Warn", "Fault", "Limit") and not line.startswith(OWNER_WARNINGS):
            self.events.post("messd", line)
        elif verb == "Ok" and answered == "Status":
            self.take_status(args)
        elif verb == "Err" and answered in (None, "Hello", "Status", "Release"):
            self.events.post("messd", line if answered is None else "%s refused: %s" % (answered, line))
        return False

    def take_status(self, args):
        fields = status_fields(args)
        if fields.get("State"):
            self.state = fields["State"][0]
        radius = numbers(fields.get("TipRadius", []), 1)
        if radius and radius[0] > 0:
            self.set_tip_radius(radius[0])
        if fields.get("Control"):
            holder = fields["Control"][0]
            self.set_control("none" if holder == "none" else " ".join(holder.rsplit("@", 1)))

    def set_control(self, holder):
        self.control = holder
        if holder == "none":
            text = "control is free: the first motion command takes it"
        elif self.holds_control():
            text = "this panel controls the machine"
        else:
            text = "controlled by %s: Release or quit it there to jog here" % holder
        self.events.post("control", text)

    def set_tip_radius(self, radius):
        if abs(radius - self.tip_radius) > 1e-9:
            self.tip_radius = radius
            marker = self.doc.getObject(MARKER)
            if marker is not None and marker.TypeId == "Part::Feature":
                placement = marker.Placement
                marker.Shape = probe_shape(radius)
                marker.Placement = placement

    # --- the document ---------------------------------------------------------------------
    def add_point(self, p, hit=None):
        """A measured point: at the Hit's point (4 decimals) when its Hit came with it, else at
        the MeasPt's (3 decimals); with the hit's number, approach and tip radius."""
        group = document_group(self.doc, POINT_GROUP, "IMESS points")
        at = hit["point"] if hit else p
        obj = self.doc.addObject("Part::Feature", "MeasPt")
        obj.Shape = Part.Vertex(at)
        number = len(group.Group) + 1
        obj.addProperty("App::PropertyVector", "Measured", "IMESS", "the point as messd sent it (mm)")
        obj.Measured = at
        if hit:
            obj.addProperty("App::PropertyInteger", "HitNumber", "IMESS", "its number in messd's hit journal (Replay)")
            obj.HitNumber = hit["seq"]
            obj.addProperty("App::PropertyVector", "Approach", "IMESS", "the unit direction the probe moved in (0 0 0: ForcePt)")
            obj.Approach = hit["approach"]
            obj.addProperty("App::PropertyFloat", "TipRadius", "IMESS", "the tip radius messd compensated (mm)")
            obj.TipRadius = hit["radius"]
        obj.Label = "MeasPt%03d" % number
        if self.feature:
            set_feature(obj, self.feature)
        group.addObject(obj)
        self.points.append(obj)
        if FreeCAD.GuiUp:
            obj.ViewObject.PointSize = POINT_SIZE
            obj.ViewObject.PointColor = POINT_COLOUR
        self.events.post("point", "%s %.4f %.4f %.4f%s" % (obj.Label, at.x, at.y, at.z,
                                                          " (hit %d)" % hit["seq"] if hit else ""))
        return obj

    def move_marker(self, p):
        """Moves the probe marker (a placement change, no recompute); True when it was created."""
        marker = self.doc.getObject(MARKER)
        created = marker is None
        if created:
            marker = self.doc.addObject("Part::Feature", MARKER)
            marker.Label = "IMESS probe"
            marker.Shape = probe_shape(self.tip_radius)
            if FreeCAD.GuiUp:
                marker.ViewObject.ShapeColor = MARKER_COLOUR
                marker.ViewObject.Selectable = False
        marker.Placement = FreeCAD.Placement(p, FreeCAD.Rotation())
        return created


def set_feature(obj, name):
    """Gives a point the plan feature it measures ("" takes it away); the label shows it."""
    if "Feature" not in obj.PropertiesList:
        obj.addProperty("App::PropertyString", "Feature", "IMESS", "the inspection plan's feature this point measures")
    obj.Feature = name
    label_point(obj)


def signed_um(mm):
    """'+1.2 µm', '-0.4 µm'; never '-0.0 µm'."""
    return "%+.1f µm" % (round(mm * 1000, 1) + 0.0)


def label_point(obj):
    """'MeasPt007', then its feature and its deviation when it has them: 'MeasPt007 bore +1.2 µm'."""
    words = [obj.Label.split(" ")[0]]
    if getattr(obj, "Feature", ""):
        words.append(obj.Feature)
    if "Deviation" in obj.PropertiesList:
        words.append(signed_um(obj.Deviation))
    obj.Label = " ".join(words)
