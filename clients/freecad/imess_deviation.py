# IMESS deviation colours for FreeCAD: the JSON of `messcap inspect … --json OUT` turned into
# coloured points. Each report point is placed where it was measured (its "machine" point, where
# the panel captured it), coloured by its deviation on its feature's tolerance scale, and judged by
# the characteristics of its feature as the report judged them.
"""Colouring measured points by their deviation from an inspection plan (testable under freecadcmd)."""

import json

import FreeCAD
import Part

from imess_capture import POINT_GROUP, POINT_SIZE, CaptureError, document_group, label_point, set_feature

DEVIATION_GROUP = "IMESS_Deviations"
MATCH_MM = 1e-3  # a report point within this of a captured point colours that point
GREEN, YELLOW, RED = (0.0, 0.75, 0.0), (1.0, 1.0, 0.0), (1.0, 0.0, 0.0)
CYAN, BLUE = (0.0, 1.0, 1.0), (0.0, 0.0, 1.0)
CAPTURED_COLOUR = (0.0, 0.55, 0.0)  # imess_capture's colour of a fresh point
_PROPERTY_GROUP = "IMESS deviation"
_PROPERTIES = ("Deviation", "Form", "Scale", "ToleranceLower", "ToleranceUpper", "InTolerance", "Characteristics",
               "DeviationColor")


def _mix(a, b, f):
    return tuple(x + (y - x) * f for x, y in zip(a, b))


def deviation_colour(d, scale, out=False):
    """(r, g, b) of deviation d on the scale +-scale: 0 green, toward yellow at +scale and cyan at
    -scale. Beyond the scale a point that is out of tolerance (`out`) is red above, blue below;
    one that is not stays yellow / cyan - red and blue always mean out of tolerance."""
    warm, cold = (YELLOW, RED), (CYAN, BLUE)
    side = warm if d >= 0 else cold
    f = abs(d) / scale if scale > 0 else (0.0 if d == 0 else float("inf"))
    if f > 1.0 and out:
        return side[1]
    return _mix(GREEN, side[0], min(f, 1.0))


def _number(value, what):
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise CaptureError("%s must be a number, not %r" % (what, value))
    return float(value)


def _vector(value, what):
    if not isinstance(value, list) or len(value) != 3:
        raise CaptureError("%s must be [x, y, z], not %r" % (what, value))
    return FreeCAD.Vector(*(_number(v, what) for v in value))


def point_band(entry, what):
    """A point's own (lower, upper) from "lower"/"upper" or "tolerance" (t = +-t, [lower, upper]);
    None without. messcap does not write these; a report written by hand may."""
    if "lower" in entry or "upper" in entry:
        if "lower" not in entry or "upper" not in entry:
            raise CaptureError("%s: give both \"lower\" and \"upper\" (or \"tolerance\")" % what)
        band = (_number(entry["lower"], what + " lower"), _number(entry["upper"], what + " upper"))
    elif "tolerance" in entry:
        t = entry["tolerance"]
        if isinstance(t, list) and len(t) == 2:
            band = (_number(t[0], what + " tolerance[0]"), _number(t[1], what + " tolerance[1]"))
        else:
            t = abs(_number(t, what + " tolerance (a number t for +-t, or [lower, upper])"))
            band = (-t, t)
    else:
        return None
    if band[0] > band[1]:
        raise CaptureError("%s: lower %g is above upper %g" % (what, band[0], band[1]))
    return band


def characteristic_scale(c, what):
    """How far a point of the characteristic's feature may deviate for the characteristic to hold,
    roughly (mm), or None (angles, no tolerance): a zone of width t (flatness, position …) t/2; a
    size (a diameter) half its largest limit, a radius the limit; a distance its largest limit."""
    if c.get("unit", "mm") != "mm" or "upper" not in c:
        return None
    upper = _number(c["upper"], what + " upper")
    if c.get("zone"):
        return upper / 2 if upper > 0 else None
    lower = _number(c.get("lower", -upper), what + " lower")
    limit = max(abs(lower), abs(upper))
    if c.get("type") == "size" and not c.get("radius"):
        limit /= 2
    return limit if limit > 0 else None


def read_report(source):
    """The inspection JSON (a path or the parsed dict) as {"points": [...], "features": {...},
    "summary": …}. A point: feature, at (where it was measured: "machine", else "xyz"), deviation,
    form, band (its own, or None). A feature: scale (the smallest of its characteristics' scales,
    or None) and verdicts [(name, True/False/None)] of every characteristic on it (a distance or an
    angle is on both its features; a datum is not judged by it)."""
    if isinstance(source, dict):
        report, name = source, "inspection report"
    else:
        name = source
        try:
            with open(source) as f:
                report = json.load(f)
        except (OSError, ValueError) as e:
            raise CaptureError("cannot read the inspection report %s: %s" % (source, e))
    points = report.get("points") if isinstance(report, dict) else None
    if not isinstance(points, list):
        raise CaptureError("%s has no \"points\" list; expected what messcap inspect --json writes: "
                           "{\"points\": [{\"feature\": NAME, \"machine\": [x, y, z], \"deviation\": d}, ...]}" % name)
    features = {}
    for i, c in enumerate(report.get("characteristics") or []):
        if not isinstance(c, dict):
            continue
        what = "%s characteristic %d" % (name, i + 1)
        scale = characteristic_scale(c, what)
        verdict = c.get("in_tolerance") if isinstance(c.get("in_tolerance"), bool) else None
        for key in ("feature", "other"):
            if isinstance(c.get(key), str):
                f = features.setdefault(c[key], {"scale": None, "verdicts": []})
                f["verdicts"].append((str(c.get("name", "")), verdict))
                if scale is not None and (f["scale"] is None or scale < f["scale"]):
                    f["scale"] = scale
    out = []
    for i, p in enumerate(points):
        what = "%s point %d" % (name, i + 1)
        if not isinstance(p, dict):
            raise CaptureError("%s must be an object, not %r" % (what, p))
        at = _vector(p["machine"], what + " \"machine\"") if "machine" in p else _vector(p.get("xyz"), what + " \"xyz\"")
        form = _number(p["form"], what + " form") if "form" in p else None
        out.append({"feature": str(p.get("feature", "")), "at": at, "deviation": _number(p.get("deviation"), what + " deviation"),
                    "form": form, "band": point_band(p, what)})
    return {"points": out, "features": features, "summary": report.get("summary"),
            "characteristics": [c for c in report.get("characteristics") or [] if isinstance(c, dict)]}


def judge(point, features, fallback_scale):
    """(scale, in_tolerance or None, characteristics text) of one report point."""
    band = point["band"]
    if band is not None:
        return max(abs(band[0]), abs(band[1])), band[0] <= point["deviation"] <= band[1], ""
    feature = features.get(point["feature"], {"scale": None, "verdicts": []})
    verdicts = feature["verdicts"]
    judged = [v for _, v in verdicts if v is not None]
    text = ", ".join("%s %s" % (n, {True: "ok", False: "OUT", None: "--"}[v]) for n, v in verdicts)
    return feature["scale"] or fallback_scale, (all(judged) if judged else None), text


def _set(obj, ptype, name, doc_text, value):
    if name not in obj.PropertiesList:
        obj.addProperty(ptype, name, _PROPERTY_GROUP, doc_text)
    setattr(obj, name, value)


def _clear(obj):
    for name in _PROPERTIES:
        if name in obj.PropertiesList:
            obj.removeProperty(name)
    label_point(obj)
    if FreeCAD.GuiUp:
        obj.ViewObject.PointColor = CAPTURED_COLOUR


def colour_points(doc, source):
    """Colours the captured point at each report point's measured position (within MATCH_MM), or
    adds a point to IMESS_Deviations there when none was captured. Colours of an earlier report are
    replaced. Returns a summary: points, matched, added, out_of_tolerance (points whose own band or
    whose feature's characteristics fail), report (the parsed report)."""
    report = read_report(source)
    points = report["points"]
    # A feature without characteristics is shown on the tightest scale of the others (its noise is
    # not blown up to yellow), without any on the report's largest deviation.
    scales = [f["scale"] for f in report["features"].values() if f["scale"] is not None]
    fallback = min(scales) if scales else max([abs(p["deviation"]) for p in points] + [0.0])
    old = doc.getObject(DEVIATION_GROUP)
    if old is not None:
        for o in list(old.Group):
            doc.removeObject(o.Name)
    captured = doc.getObject(POINT_GROUP)
    candidates = [o for o in (captured.Group if captured is not None else []) if hasattr(o, "Measured")]
    for o in candidates:
        if "Deviation" in o.PropertiesList:
            _clear(o)
    summary = {"points": len(points), "matched": 0, "added": 0, "out_of_tolerance": 0, "report": report}
    for p in points:
        obj = min(candidates, key=lambda o: (o.Measured - p["at"]).Length, default=None)
        if obj is not None and (obj.Measured - p["at"]).Length <= MATCH_MM and "Deviation" not in obj.PropertiesList:
            summary["matched"] += 1
        else:
            obj = doc.addObject("Part::Feature", "Deviation")
            obj.Shape = Part.Vertex(p["at"])
            obj.Label = "Deviation"
            document_group(doc, DEVIATION_GROUP, "IMESS deviations").addObject(obj)
            summary["added"] += 1
        d = p["deviation"]
        scale, inside, verdicts = judge(p, report["features"], fallback)
        colour = deviation_colour(d, scale, out=inside is False)
        if p["feature"]:
            set_feature(obj, p["feature"])
        _set(obj, "App::PropertyFloat", "Deviation", "deviation from the plan's nominal (mm)", d)
        if p["form"] is not None:
            _set(obj, "App::PropertyFloat", "Form", "deviation from the fitted feature (mm)", p["form"])
        _set(obj, "App::PropertyFloat", "Scale", "the colour scale: yellow at +Scale, cyan at -Scale (mm)", scale)
        if p["band"] is not None:
            _set(obj, "App::PropertyFloat", "ToleranceLower", "the point's lowest deviation in tolerance (mm)", p["band"][0])
            _set(obj, "App::PropertyFloat", "ToleranceUpper", "the point's highest deviation in tolerance (mm)", p["band"][1])
        if inside is not None:
            _set(obj, "App::PropertyBool", "InTolerance",
                 "its own band holds, else every characteristic of its feature is in tolerance", inside)
            summary["out_of_tolerance"] += 0 if inside else 1
        if verdicts:
            _set(obj, "App::PropertyString", "Characteristics", "the report's verdicts on its feature", verdicts)
        _set(obj, "App::PropertyColor", "DeviationColor", "the colour shown for the deviation", colour)
        label_point(obj)
        if FreeCAD.GuiUp:
            obj.ViewObject.PointColor = colour
            obj.ViewObject.PointSize = POINT_SIZE + 2
    doc.recompute()
    return summary
