# Inside freecadcmd: the plugin's line and cone fits and its Distance / Angle buttons, all
# computed by messcap (fit, relate) on points made from known geometry; the FreeCAD objects
# must carry the known values and shapes, and what cannot be related must say why.
# argv: BIN_DIR SOURCE_DIR
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from plugin_test import MESSCAP, Gui, check, finish, panel_module  # noqa: E402

import FreeCAD  # noqa: E402
import Part  # noqa: E402
import imess_fit  # noqa: E402

V = FreeCAD.Vector


def vertices(doc, points, name):
    """Point objects as the capture makes them (Part.Vertex features)."""
    objs = []
    for p in points:
        o = doc.addObject("Part::Feature", name)
        o.Shape = Part.Vertex(p)
        objs.append(o)
    return objs


def frame(axis):
    """Two unit vectors square to axis and to each other."""
    u = axis.cross(V(1, 0, 0) if abs(axis.x) < 0.9 else V(0, 1, 0))
    u.normalize()
    return u, axis.cross(u)


def parallel(a, b, tol=1e-6):
    return abs(abs(a.dot(b)) - a.Length * b.Length) < tol


def line_and_cone(doc):
    d = V(3, 4, 12)
    d.normalize()
    u, w = frame(d)
    origin = V(5, -2, 7)
    # Pairs 0.02 apart across the line: the best line is the one they were made from, rms 0.01.
    pts = [origin + d * t + u * s for t in (0, 10, 20, 30, 40, 50) for s in (0.01, -0.01)]
    line = imess_fit.fit_feature(doc, "line", vertices(doc, pts, "L"), MESSCAP)
    check(line.FitType == "line" and parallel(line.Direction, d), "line direction %s, made along %s" % (line.Direction, d))
    check((line.FitPoint - (origin + d * 25)).Length < 1e-6, "line point is the centroid: %s" % line.FitPoint)
    edge = line.Shape.Edges[0] if line.Shape.Edges else None
    check(edge is not None and abs(edge.Length - 50) < 1e-6, "the line is an edge over the points' extent (50 mm)")
    check(abs(line.RMS - 0.01) < 1e-6, "line rms %.6f, the offsets were 0.01" % line.RMS)

    apex, axis, half = V(10, 20, 30), V(0.2, -0.1, 1), math.radians(15)
    axis.normalize()
    u, w = frame(axis)
    pts = [apex + axis * h + (u * math.cos(a) + w * math.sin(a)) * (h * math.tan(half))
           for h in (10, 17, 24, 31) for a in (0.3, 1.3, 2.3, 3.3, 4.3, 5.3)]
    cone = imess_fit.fit_feature(doc, "cone", vertices(doc, pts, "C"), MESSCAP)
    check(abs(cone.ApexAngle - 30) < 1e-6, "cone apex angle %.6f, made 30" % cone.ApexAngle)
    check((cone.Apex - apex).Length < 1e-5, "cone apex %s, made at %s" % (cone.Apex, apex))
    check(cone.Axis.dot(axis) > 1 - 1e-9, "cone axis points toward the wider end: %s" % cone.Axis)
    faces = [f for f in cone.Shape.Faces if f.Surface.TypeId == "Part::GeomCone"]
    check(len(faces) == 1, "the cone is a conical solid: %s" % [f.Surface.TypeId for f in cone.Shape.Faces])
    if faces:
        radius = faces[0].Surface.Radius  # at the surface's location: the end nearest the apex
        check(abs(radius - 10 * math.tan(half)) < 1e-4, "it starts at the nearest points' radius: %.6f" % radius)
    check(cone.Label == "cone D%.4f" % cone.Diameter, "cone label %r" % cone.Label)
    check(cone.Result.startswith("Ø %.4f mm, apex 30.0000°, form " % cone.Diameter) and cone.Result.endswith(" µm, rms 0.0 µm, 24 points"),
          "cone result in words: %r" % cone.Result)


def relations(doc):
    mod, warnings, _ = panel_module()
    panel = mod.CapturePanel()
    face = imess_fit.fit_feature(doc, "plane", vertices(doc, [V(0, 0, 0), V(100, 0, 0), V(0, 80, 0), V(100, 80, 0)], "F"),
                                 MESSCAP)
    bore = imess_fit.fit_feature(doc, "circle", vertices(doc, [V(60, 40, 12), V(50, 50, 12), V(40, 40, 12)], "B"), MESSCAP)
    tilt = math.radians(60)  # a face at 60 degrees to the first
    slope = imess_fit.fit_feature(doc, "plane", vertices(doc, [V(0, 0, 50), V(100, 0, 50), V(0, 40 * math.cos(tilt),
                                  50 + 40 * math.sin(tilt))], "S"), MESSCAP)
    ball = imess_fit.fit_feature(doc, "sphere", vertices(doc, [V(5, 0, 0), V(-5, 0, 0), V(0, 5, 0), V(0, 0, 5)], "P"),
                                 MESSCAP)

    Gui.selected = [face, bore]
    panel.relate("distance")
    dist = [o for o in doc.Objects if hasattr(o, "RelateJSON")]
    check(len(dist) == 1 and abs(dist[0].Distance - 12) < 1e-9 and dist[0].DistanceRule == "plane-point",
          "Distance face-bore: 12 mm, plane-point")
    if dist:
        e = dist[0].Shape.Edges[0]
        check((e.Vertexes[0].Point - V(50, 40, 0)).Length < 1e-9 and (e.Vertexes[1].Point - V(50, 40, 12)).Length < 1e-9,
              "the distance is drawn from the face to the bore centre")
        check(dist[0].Label.startswith("distance 12.0000") and dist[0].Features == [face, bore],
              "labelled with the value, linked to A and B: %r" % dist[0].Label)
        check(abs(dist[0].Angle - 90) < 1e-6 and dist[0].AngleRule == "plane-axis", "and it knows the angle too")
    Gui.selected = [bore, slope]
    panel.relate("angle")
    angle = [o for o in doc.Objects if hasattr(o, "RelateJSON") and o.Label.startswith("angle")]
    check(len(angle) == 1 and abs(angle[0].Angle - 30) < 1e-6, "Angle bore axis to a 60-degree face: 30 degrees (%s)"
          % [a.Angle for a in angle])
    check(panel.events.text("fit") == (angle[0].Label if angle else None), "the events show it: %s" % panel.events.lines())
    check(panel.results()[:2] == [("angle %s-%s" % (bore.Label, slope.Label), "30.0000° (axis-plane)"),
                                  ("distance %s-%s" % (face.Label, bore.Label), "12.0000 mm (plane-point)")],
          "both in the panel's results, newest first: %s" % panel.results())

    Gui.selected = [face, slope]
    panel.relate("distance")
    check(len(warnings) == 1 and "not parallel (60 deg > 1 deg)" in warnings[0], "faces at 60 degrees have no distance: %s"
          % warnings)
    Gui.selected = [ball, face]
    panel.relate("angle")
    check(len(warnings) == 2 and "sphere has no direction" in warnings[-1], "a sphere has no angle: %s" % warnings[-1:])
    Gui.selected = [face, doc.getObject("F")]
    panel.relate("distance")
    check(len(warnings) == 3 and "is not a fitted feature" in warnings[-1], "a point is no feature: %s" % warnings[-1:])
    before = len(warnings)
    Gui.selected = [face]
    panel.relate("distance")
    check(len(warnings) == before and "select two fitted features" in panel.events.text("fit"), "one selected: a hint")
    check(len([o for o in doc.Objects if hasattr(o, "RelateJSON")]) == 2, "failed relations add nothing")


def run():
    doc = FreeCAD.newDocument("features")
    line_and_cone(doc)
    relations(doc)
    FreeCAD.closeDocument(doc.Name)


finish("freecad features", run)
