# IMESS view following for FreeCAD: the 3-D view is fitted to the probe and the points (the scans'
# too) as they come, at least a part's size across, until the user moves the view; the box logic runs without
# the GUI, the camera part only in a real FreeCAD window.
"""Keeping the probe and the measured points in view."""

import FreeCAD

MIN_VIEW_MM = 80.0  # the smallest region shown: a part's scale, not the probe's
GROW = 1.4          # the view is fitted to the box grown this much: a probe moving inside it does not refit
ISOMETRIC = (0.424708, 0.17592, 0.339851, 0.820473)  # FreeCAD's isometric view, as a quaternion


def extend(extent, p):
    """The (low, high) corners of extent and the point p."""
    if extent is None:
        return FreeCAD.Vector(p), FreeCAD.Vector(p)
    low, high = extent
    return (FreeCAD.Vector(min(low.x, p.x), min(low.y, p.y), min(low.z, p.z)),
            FreeCAD.Vector(max(high.x, p.x), max(high.y, p.y), max(high.z, p.z)))


def target_box(position, extent, tip_radius):
    """(low, high) corners of what must be seen: the probe with its stylus and the points'
    extent, at least MIN_VIEW_MM across in each direction; None when there is nothing yet."""
    box = extent
    if position is not None:
        r = max(tip_radius, 0.5)
        box = extend(extend(box, position - FreeCAD.Vector(r, r, r)), position + FreeCAD.Vector(r, r, 13 * r))
    if box is None:
        return None
    low, high = FreeCAD.Vector(box[0]), FreeCAD.Vector(box[1])
    for i in range(3):
        half = max(high[i] - low[i], MIN_VIEW_MM) / 2
        middle = (low[i] + high[i]) / 2
        low[i], high[i] = middle - half, middle + half
    return low, high


def inside(box, outer):
    return outer is not None and all(outer[0][i] <= box[0][i] and box[1][i] <= outer[1][i] for i in range(3))


def grown(box, factor):
    middle = (box[0] + box[1]) * 0.5
    half = (box[1] - box[0]) * (0.5 * factor)
    return middle - half, middle + half


def camera_state(view):
    """What the user changes by moving the view: the camera's position, orientation and zoom."""
    cam = view.getCameraNode()
    zoom = cam.height.getValue() if hasattr(cam, "height") else cam.heightAngle.getValue()
    values = list(cam.position.getValue().getValue()) + list(cam.orientation.getValue().getValue()) + [zoom]
    return tuple(round(v, 4) for v in values)


class ViewFollower:
    """Fits a FreeCAD 3-D view to target_box() whenever the probe or a point leaves what it shows,
    until the view's camera is moved by someone else; then `following` turns off (the panel's
    Follow box turns it on again)."""

    def __init__(self, events):
        self.events = events
        self.following = True
        self.fitted = None   # the box the view was last fitted to
        self.camera = None   # camera_state() right after that fit
        self.view = None
        self.oriented = None  # the view turned isometric at its first fit (later fits keep the direction)
        self.extent = None   # of the points seen so far
        self.seen = 0

    def follow(self, on=True):
        """Turns following on (fitting at once) or off; on also starts counting points afresh."""
        self.following = on
        self.fitted = self.camera = None
        self.extent, self.seen = None, 0
        if on:
            self.events.clear("view")

    def update(self, view, position, points, tip_radius, scanned=None):
        """Called from the panel's timer with the probe position, the point objects (each
        with `Measured`, new ones appended) and the scans' (low, high) extent; True when the view
        was fitted."""
        for o in points[self.seen:]:
            self.extent = extend(self.extent, o.Measured)
        self.seen = len(points)
        if scanned is not None:
            self.extent = extend(extend(self.extent, scanned[0]), scanned[1])
        if not self.following or view is None:
            return False
        if view is not self.view:
            self.view, self.fitted, self.camera = view, None, None
        if self.camera is not None and camera_state(view) != self.camera:
            self.following = False
            self.events.post("view", "the view was moved: it no longer follows the probe (tick Follow to follow again)")
            return False
        box = target_box(position, self.extent, tip_radius)
        if box is None or inside(box, self.fitted):
            return False
        first = view is not self.oriented
        self.oriented = view
        self.fitted = grown(box, GROW)
        fit(view, self.fitted, isometric=first)
        self.camera = camera_state(view)
        return True


def fit(view, box, isometric=False):
    """Shows the box in the view (its direction kept, or isometric), without animation."""
    from pivy import coin  # only in the GUI

    cam = view.getCameraNode()
    if isometric:
        cam.orientation.setValue(coin.SbRotation(*ISOMETRIC))
    region = view.getViewer().getSoRenderManager().getViewportRegion()
    (x0, y0, z0), (x1, y1, z1) = tuple(box[0]), tuple(box[1])
    cam.viewBoundingBox(coin.SbBox3f(x0, y0, z0, x1, y1, z1), region.getViewportAspectRatio(), 1.0)
