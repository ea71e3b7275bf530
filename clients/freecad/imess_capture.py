# IMESS live capture for FreeCAD, without the GUI: reads messd's protocol lines from a
# non-blocking socket, moves a probe marker with CurrCor, adds every MeasPt to the document at
# once, and fits selected points through `messcap fit KIND -` (the C++ metrology library).
"""IMESS capture logic for FreeCAD (testable under freecadcmd; the GUI macro only wires it)."""

import errno
import json
import os
import shutil
import socket
import subprocess

import FreeCAD
import Part

DEFAULT_HOST = "localhost"
DEFAULT_PORT = 1066
POINT_GROUP = "IMESS_Points"
FEATURE_GROUP = "IMESS_Features"
MARKER = "IMESS_Probe"
FIT_KINDS = ("plane", "circle", "sphere", "cylinder")
MAX_LINE = 4096  # messd lines are short; a longer one is noise and is dropped


class CaptureError(Exception):
    """Connecting, reading or fitting failed; the message says what and why."""


def find_messcap():
    """messcap: $IMESS_MESSCAP, else on PATH, else build/bin/messcap of this source tree."""
    candidates = [os.environ.get("IMESS_MESSCAP"), shutil.which("messcap"),
                  os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "build", "bin", "messcap")]
    for c in candidates:
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return os.path.abspath(c)
    raise CaptureError("messcap not found: set IMESS_MESSCAP, put messcap on PATH, or build it "
                       "(scripts/run builds build/bin/messcap)")


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

    def __init__(self, doc, host=DEFAULT_HOST, port=DEFAULT_PORT, sock=None, marker_radius=1.0):
        self.doc = doc
        self.host, self.port = host, int(port)
        self.sock = sock
        self.marker_radius = marker_radius
        self.buffer = b""
        self.position = None
        self.state = ""
        self.messages = []  # Warn / Fault / Err lines, newest last
        self.points = []    # the point objects this session created, in order
        self.closed_reason = ""
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
        self.send("Hello FreeCAD")

    def connected(self):
        return self.sock is not None

    def send(self, line):
        if self.sock is None:
            raise CaptureError("not connected")
        data = (line.rstrip("\n") + "\n").encode("ascii")
        self.sock.setblocking(True)
        try:
            self.sock.sendall(data)
        finally:
            self.sock.setblocking(False)

    def close(self, reason="closed"):
        if self.sock is not None:
            try:
                self.sock.close()
            finally:
                self.sock = None
                self.closed_reason = reason

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
    def group(self, name, label):
        g = self.doc.getObject(name)
        if g is None:
            g = self.doc.addObject("App::DocumentObjectGroup", name)
            g.Label = label
        return g

    def add_point(self, p):
        group = self.group(POINT_GROUP, "IMESS points")
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


# --- fitting ------------------------------------------------------------------------------
def points_of(objects):
    """Every vertex of the given objects (measured points or any shape), in order."""
    pts = []
    for o in objects:
        shape = getattr(o, "Shape", None)
        if shape is not None and not shape.isNull():
            pts.extend(v.Point for v in shape.Vertexes)
        elif hasattr(o, "Points"):  # Points::Feature (an imported .asc / .ply cloud)
            pts.extend(o.Points.Points)
    return pts


def run_fit(kind, points, messcap=None):
    """`messcap fit KIND -` with the points on stdin; returns its JSON as a dict."""
    if kind not in FIT_KINDS:
        raise CaptureError("unknown feature kind %r; accepted: %s" % (kind, ", ".join(FIT_KINDS)))
    text = "".join("%r %r %r\n" % (p.x, p.y, p.z) for p in points)
    exe = messcap or find_messcap()
    r = subprocess.run([exe, "fit", kind, "-"], input=text, capture_output=True, text=True, timeout=30)
    if r.returncode != 0:
        raise CaptureError(r.stderr.strip() or "messcap fit %s failed (exit %d)" % (kind, r.returncode))
    return json.loads(r.stdout)


def _vector(values):
    return FreeCAD.Vector(*values)


def _span(points, origin, direction):
    ts = [(p - origin).dot(direction) for p in points]
    return min(ts), max(ts)


def feature_shape(fit, points):
    """Real FreeCAD geometry for a fit: plane face over the points, circle edge, sphere, cylinder."""
    kind = fit["type"]
    if kind == "plane":
        plane = Part.Plane(_vector(fit["point"]), _vector(fit["normal"]))
        uv = [plane.parameter(p) for p in points]
        us, vs = [c[0] for c in uv], [c[1] for c in uv]
        margin = 0.1 * max(max(us) - min(us), max(vs) - min(vs), 1.0)
        return plane.toShape(min(us) - margin, max(us) + margin, min(vs) - margin, max(vs) + margin)
    if kind == "circle":
        return Part.Circle(_vector(fit["center"]), _vector(fit["normal"]), fit["diameter"] / 2).toShape()
    if kind == "sphere":
        return Part.makeSphere(fit["diameter"] / 2, _vector(fit["center"]))
    if kind == "cylinder":
        axis, origin = _vector(fit["axis"]), _vector(fit["point"])
        lo, hi = _span(points, origin, axis)
        height = max(hi - lo, 1e-3)
        return Part.makeCylinder(fit["diameter"] / 2, height, origin + axis * lo, axis)
    raise CaptureError("no geometry for a fitted %s" % kind)


_PROPERTIES = (  # JSON key -> (property type, name, description)
    ("type", "App::PropertyString", "FitType", "the fitted feature kind"),
    ("point", "App::PropertyVector", "FitPoint", "plane: centroid; cylinder: on the axis (mm)"),
    ("normal", "App::PropertyVector", "Normal", "unit normal"),
    ("center", "App::PropertyVector", "Center", "centre (mm)"),
    ("axis", "App::PropertyVector", "Axis", "unit axis"),
    ("diameter", "App::PropertyFloat", "Diameter", "diameter (mm)"),
    ("rms", "App::PropertyFloat", "RMS", "rms of the residuals (mm)"),
    ("form_min", "App::PropertyFloat", "FormMin", "most negative residual (mm)"),
    ("form_max", "App::PropertyFloat", "FormMax", "most positive residual (mm)"),
    ("n", "App::PropertyInteger", "PointCount", "points fitted"),
)


def fit_feature(doc, kind, objects, messcap=None):
    """Fits KIND to the objects' points with messcap and adds the feature to the document."""
    points = points_of(objects)
    fit = run_fit(kind, points, messcap)
    shape = feature_shape(fit, points)
    group = doc.getObject(FEATURE_GROUP)
    if group is None:
        group = doc.addObject("App::DocumentObjectGroup", FEATURE_GROUP)
        group.Label = "IMESS features"
    obj = doc.addObject("Part::Feature", "Fit" + kind.capitalize())
    obj.Shape = shape
    for key, ptype, name, doc_text in _PROPERTIES:
        if key in fit:
            obj.addProperty(ptype, name, "IMESS fit", doc_text)
            value = fit[key]
            setattr(obj, name, _vector(value) if ptype == "App::PropertyVector" else value)
    obj.addProperty("App::PropertyString", "FitJSON", "IMESS fit", "messcap fit output, verbatim")
    obj.FitJSON = json.dumps(fit)
    obj.addProperty("App::PropertyLinkList", "FitPoints", "IMESS fit", "the points fitted")
    obj.FitPoints = list(objects)
    if "diameter" in fit:
        obj.Label = "%s D%.3f" % (kind, fit["diameter"])
    else:
        obj.Label = kind
    group.addObject(obj)
    doc.recompute()
    return obj
