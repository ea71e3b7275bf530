# IMESS fits and relations for FreeCAD: selected points go through `messcap fit KIND -`, two
# fitted features through `messcap relate -` (the C++ library computes; this file only builds
# the FreeCAD geometry and properties from the JSON messcap prints).
"""Fitting and relating features with messcap (testable under freecadcmd)."""

import json
import math
import subprocess

import FreeCAD
import Part

from imess_capture import CaptureError, document_group, find_messcap, xyz_text

FEATURE_GROUP = "IMESS_Features"
RELATION_GROUP = "IMESS_Relations"
FIT_KINDS = ("plane", "circle", "sphere", "cylinder", "line", "cone")


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


def run_messcap(args, text, messcap=None):
    """messcap ARGS with `text` on stdin; returns its JSON output as a dict."""
    exe = messcap or find_messcap()
    r = subprocess.run([exe] + list(args), input=text, capture_output=True, text=True, timeout=30)
    if r.returncode != 0:
        raise CaptureError(r.stderr.strip() or "messcap %s failed (exit %d)" % (" ".join(args), r.returncode))
    return json.loads(r.stdout)


def run_fit(kind, points, messcap=None):
    """`messcap fit KIND -` with the points on stdin; returns its JSON as a dict."""
    if kind not in FIT_KINDS:
        raise CaptureError("unknown feature kind %r; accepted: %s" % (kind, ", ".join(FIT_KINDS)))
    return run_messcap(["fit", kind, "-"], xyz_text(points), messcap)


def _vector(values):
    return FreeCAD.Vector(*values)


def _span(points, origin, direction):
    ts = [(p - origin).dot(direction) for p in points]
    return min(ts), max(ts)


def feature_shape(fit, points):
    """Real FreeCAD geometry for a fit: a plane face over the points, a circle edge, a sphere, a
    cylinder or cone frustum and a line segment over the points' extent."""
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
    if kind == "line":
        direction, origin = _vector(fit["direction"]), _vector(fit["point"])
        lo, hi = _span(points, origin, direction)
        return Part.LineSegment(origin + direction * lo, origin + direction * max(hi, lo + 1e-3)).toShape()
    if kind == "cone":
        axis, origin = _vector(fit["axis"]), _vector(fit["point"])
        lo, hi = _span(points, origin, axis)
        slope = math.tan(math.radians(fit["apex_angle_deg"] / 2))
        radius = lambda t: max(fit["diameter"] / 2 + t * slope, 0.0)  # noqa: E731 - along the axis from `point`
        hi = max(hi, lo + 1e-3)
        return Part.makeCone(radius(lo), radius(hi), hi - lo, origin + axis * lo, axis)
    raise CaptureError("no geometry for a fitted %s" % kind)


_PROPERTIES = (  # JSON key -> (property type, name, description)
    ("type", "App::PropertyString", "FitType", "the fitted feature kind"),
    ("point", "App::PropertyVector", "FitPoint", "line, plane: centroid; cylinder, cone: on the axis (mm)"),
    ("direction", "App::PropertyVector", "Direction", "line: unit direction"),
    ("normal", "App::PropertyVector", "Normal", "unit normal"),
    ("center", "App::PropertyVector", "Center", "centre (mm)"),
    ("axis", "App::PropertyVector", "Axis", "unit axis (cone: toward increasing radius)"),
    ("diameter", "App::PropertyFloat", "Diameter", "diameter (mm; cone: through FitPoint)"),
    ("apex", "App::PropertyVector", "Apex", "cone: the apex (mm)"),
    ("apex_angle_deg", "App::PropertyFloat", "ApexAngle", "cone: full apex angle (degrees)"),
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
    group = document_group(doc, FEATURE_GROUP, "IMESS features")
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
    obj.addProperty("App::PropertyString", "Result", "IMESS fit", "the fit in words, lengths to 0.1 µm")
    obj.Result = fit_text(fit)
    obj.Label = "%s D%.4f" % (kind, fit["diameter"]) if "diameter" in fit else kind
    group.addObject(obj)
    doc.recompute()
    return obj


def um(mm):
    """A length in µm with 0.1 µm resolution: '1.2 µm'."""
    return "%.1f µm" % (mm * 1000)


def fit_text(fit):
    """'Ø 30.0012 mm, form 1.2 µm, rms 0.4 µm, 8 points' (form: the residuals' range)."""
    words = []
    if "diameter" in fit:
        words.append("Ø %.4f mm" % fit["diameter"])
    if "apex_angle_deg" in fit:
        words.append("apex %.4f°" % fit["apex_angle_deg"])
    if "form_min" in fit and "form_max" in fit:
        words.append("form %s" % um(fit["form_max"] - fit["form_min"]))
    if "rms" in fit:
        words.append("rms %s" % um(fit["rms"]))
    if "n" in fit:
        words.append("%d points" % fit["n"])
    return ", ".join(words)


# --- relating two fitted features -----------------------------------------------------------
RELATE_VALUES = ("distance", "angle")


def fit_json_of(obj):
    """The messcap fit object a fitted feature keeps in FitJSON."""
    text = getattr(obj, "FitJSON", "")
    if not text:
        raise CaptureError("%s is not a fitted feature: select two features made by the fit buttons" % obj.Label)
    return text


def run_relate(fit_a, fit_b, messcap=None):
    """`messcap relate -` with the two fit objects on stdin (A the reference); returns its JSON."""
    text = "%s\n%s\n" % (json.dumps(fit_a) if isinstance(fit_a, dict) else fit_a,
                          json.dumps(fit_b) if isinstance(fit_b, dict) else fit_b)
    return run_messcap(["relate", "-"], text, messcap)


def relate_features(doc, value, a, b, messcap=None):
    """The distance or angle (`value`) of fitted features a (the reference) and b, as an object.

    The object holds both values messcap gave (Distance, Angle, their rules, the notes) and, when
    there is a distance, the segment from A to B as its shape. Raises CaptureError when the
    asked-for value is not defined (the message carries messcap's note).
    """
    if value not in RELATE_VALUES:
        raise CaptureError("unknown relation %r; accepted: %s" % (value, ", ".join(RELATE_VALUES)))
    rel = run_relate(fit_json_of(a), fit_json_of(b), messcap)
    key = "distance" if value == "distance" else "angle_deg"
    if key not in rel:
        raise CaptureError("no %s between %s and %s: %s" % (value, a.Label, b.Label, "; ".join(rel.get("notes", []))))
    obj = doc.addObject("Part::Feature", "Distance" if value == "distance" else "Angle")
    if "distance" in rel:
        start, end = _vector(rel["from"]), _vector(rel["to"])
        obj.Shape = Part.LineSegment(start, end).toShape() if (end - start).Length > 1e-9 else Part.Vertex(start)
        obj.addProperty("App::PropertyFloat", "Distance", "IMESS relation", "distance A to B (mm)")
        obj.Distance = rel["distance"]
        obj.addProperty("App::PropertyString", "DistanceRule", "IMESS relation", "how it was measured (docs/metrology.md 12.1)")
        obj.DistanceRule = rel["distance_rule"]
    if "angle_deg" in rel:
        obj.addProperty("App::PropertyFloat", "Angle", "IMESS relation", "angle A to B, 0..90 degrees")
        obj.Angle = rel["angle_deg"]
        obj.addProperty("App::PropertyString", "AngleRule", "IMESS relation", "axis-axis, axis-plane or plane-plane")
        obj.AngleRule = rel["angle_rule"]
    obj.addProperty("App::PropertyString", "Notes", "IMESS relation", "why a value is missing")
    obj.Notes = "; ".join(rel.get("notes", []))
    obj.addProperty("App::PropertyString", "RelateJSON", "IMESS relation", "messcap relate output, verbatim")
    obj.RelateJSON = json.dumps(rel)
    obj.addProperty("App::PropertyLinkList", "Features", "IMESS relation", "A (the reference), B")
    obj.Features = [a, b]
    if value == "distance":
        obj.Label = "distance %.4f %s-%s" % (rel["distance"], a.Label, b.Label)
    else:
        obj.Label = "angle %.4f deg %s-%s" % (rel["angle_deg"], a.Label, b.Label)
    obj.addProperty("App::PropertyString", "Result", "IMESS relation", "the value asked for, in words")
    obj.Result = ("%.4f mm (%s)" % (rel["distance"], rel["distance_rule"]) if value == "distance"
                  else "%.4f° (%s)" % (rel["angle_deg"], rel["angle_rule"]))
    document_group(doc, RELATION_GROUP, "IMESS distances and angles").addObject(obj)
    doc.recompute()
    return obj
