# IMESS scans for FreeCAD, without the GUI: messd's `Scan seq id x y z i j k r t` lines (hundreds a
# second while a measuring probe scans) become one point cloud per scan — a Points::Feature of
# FreeCAD's Points workbench, named Scan_<id> — filled in batches: the capture session gathers a
# poll's points and flush() adds them at once, one recompute per poll, not per point.
"""Scan point clouds in a FreeCAD document (testable under freecadcmd)."""

import FreeCAD
import Points

SCAN_GROUP = "IMESS_Scans"
SCAN_COLOUR = (0.76, 0.09, 0.36)  # magenta, as the web panel's scans: apart from the hits' green
SCAN_POINT_SIZE = 3  # pixels: thousands of points, smaller than a hit's


def parse_scan(args):
    """'seq id x y z i j k r t' -> {"seq", "id", "point", "direction", "radius"}, or None."""
    words = args.split()
    if len(words) != 10:
        return None
    try:
        v = [float(w) for w in words]
    except ValueError:
        return None
    if v[0] != int(v[0]) or v[1] != int(v[1]):
        return None
    return {"seq": int(v[0]), "id": int(v[1]), "point": FreeCAD.Vector(*v[2:5]),
            "direction": FreeCAD.Vector(*v[5:8]), "radius": v[8]}


class ScanClouds:
    """The scans of one capture session in its document.

    add() takes a parsed Scan line, end() a scan's Done or Failed; nothing touches the document
    until flush(), which appends every scan's new points to its cloud (made at its first batch:
    `Scan_<id>` in the group IMESS_Scans; a scan id used again after its scan ended gets a new
    cloud, `Scan_<id>_2` …). `points` counts the scan points in the document,
    `extent` is their (low, high) corners."""

    def __init__(self, doc, events=None):
        self.doc = doc
        self.events = events
        self.open = {}      # scan id -> its cloud, while the scan runs
        self.batch = []     # (id, parsed scan) and (id, "done" | "failed: reason"), in order, not in the document yet
        self.normals = {}   # cloud name -> [outward surface normals], written when the scan ends
        self.clouds = []    # every cloud made, in order
        self.points = 0
        self.extent = None

    def add(self, scan):
        self.batch.append((scan["id"], scan))

    def end(self, scan_id, how):
        self.batch.append((scan_id, how))

    def flush(self):
        """Puts the gathered points into their clouds; True when the document changed."""
        if not self.batch:
            return False
        batch, self.batch = self.batch, []
        new = {}       # cloud name -> (cloud, [scans])
        ended = []     # (cloud, how)
        for scan_id, item in batch:
            cloud = self.open.get(scan_id)
            if isinstance(item, str):  # its Done or Failed: a later scan of that id is another cloud
                if cloud is not None:
                    del self.open[scan_id]
                    ended.append((cloud, item))
                continue
            if cloud is None:
                cloud = self.open[scan_id] = self.make_cloud(scan_id, item)
            new.setdefault(cloud.Name, (cloud, []))[1].append(item)
        for cloud, scans in new.values():
            kernel = cloud.Points.copy()
            kernel.addPoints([s["point"] for s in scans])
            cloud.Points = kernel
            cloud.LastHit = scans[-1]["seq"]
            self.normals[cloud.Name].extend(-s["direction"] for s in scans)
            self.points += len(scans)
            for s in scans:
                self.extend(s["point"])
            self.post(cloud)
        for cloud, how in ended:
            self.finish(cloud, how)
        return True

    def close(self, how):
        """The link ended: every running scan's cloud is kept as far as it came (its Ended says
        how); True when the document changed."""
        changed = self.flush()
        for scan_id in list(self.open):
            self.finish(self.open.pop(scan_id), how)
            changed = True
        return changed

    def make_cloud(self, scan_id, scan):
        group = self.doc.getObject(SCAN_GROUP)
        if group is None:
            group = self.doc.addObject("App::DocumentObjectGroup", SCAN_GROUP)
            group.Label = "IMESS scans"
        name, again = "Scan_%d" % scan_id, 1
        while self.doc.getObject(name) is not None:  # the id used again: Scan_5_2 (FreeCAD would make it Scan_6)
            again += 1
            name = "Scan_%d_%d" % (scan_id, again)
        cloud = self.doc.addObject("Points::Feature", name)
        cloud.Label = cloud.Name
        for kind, name, doc in (("App::PropertyInteger", "ScanId", "the scan's id (ScanLine, ScanCirc)"),
                                ("App::PropertyInteger", "FirstHit", "its first point's number in messd's journal"),
                                ("App::PropertyInteger", "LastHit", "its last point's number so far"),
                                ("App::PropertyFloat", "TipRadius", "the tip radius messd compensated (mm)"),
                                ("App::PropertyString", "Ended", "done, failed: reason, or empty while it runs"),
                                ("Points::PropertyNormalList", "Normal",
                                 "each point's outward surface normal as measured (written when the scan ends)")):
            cloud.addProperty(kind, name, "IMESS", doc)
        cloud.ScanId = scan_id
        cloud.FirstHit = cloud.LastHit = scan["seq"]
        cloud.TipRadius = scan["radius"]
        group.addObject(cloud)
        if FreeCAD.GuiUp:
            cloud.ViewObject.PointSize = SCAN_POINT_SIZE
            cloud.ViewObject.ShapeColor = SCAN_COLOUR
        self.normals[cloud.Name] = []
        self.clouds.append(cloud)
        return cloud

    def finish(self, cloud, how):
        cloud.Ended = how
        cloud.Normal = self.normals.pop(cloud.Name, [])
        self.post(cloud)

    def post(self, cloud):
        if self.events is not None:
            self.events.post("scan", "%s: %d points%s" % (cloud.Label, cloud.Points.CountPoints,
                                                          " (%s)" % cloud.Ended if cloud.Ended else ""))

    def extend(self, p):
        if self.extent is None:
            self.extent = (FreeCAD.Vector(p), FreeCAD.Vector(p))
            return
        low, high = self.extent
        low.x, low.y, low.z = min(low.x, p.x), min(low.y, p.y), min(low.z, p.z)
        high.x, high.y, high.z = max(high.x, p.x), max(high.y, p.y), max(high.z, p.z)
