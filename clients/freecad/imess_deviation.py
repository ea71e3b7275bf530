# IMESS deviation colours for FreeCAD: the JSON of `messcap inspect PLAN --points FILE --json OUT`
# ("points": feature, xyz, deviation; characteristics with tolerances) turned into coloured
# points - on a scale symmetric around 0, with the tolerance band when the JSON gives one.
"""Colouring measured points by their deviation from an inspection plan (testable under freecadcmd)."""

import json
import os
import subprocess
import tempfile

import FreeCAD
import Part

from imess_capture import POINT_GROUP, CaptureError, document_group, find_messcap, xyz_text

DEVIATION_GROUP = "IMESS_Deviations"
MATCH_MM = 1e-3  # an inspected point within this of a captured point colours that point
GREEN, YELLOW, RED = (0.0, 0.75, 0.0), (1.0, 1.0, 0.0), (1.0, 0.0, 0.0)
CYAN, BLUE = (0.0, 1.0, 1.0), (0.0, 0.0, 1.0)
CAPTURED_COLOUR = (0.0, 0.6, 0.0)  # imess_capture's colour of a fresh point
_PROPERTY_GROUP = "IMESS deviation"
_PROPERTIES = ("Deviation", "Feature", "ToleranceLower", "ToleranceUpper", "InTolerance", "DeviationColor")


def _mix(a, b, f):
    return tuple(x + (y - x) * f for x, y in zip(a, b))


def deviation_colour(d, scale, band=None):
    """(r, g, b) of deviation d. 0 is green; positive runs toward yellow and red, negative toward
    cyan and blue, symmetrically. With a band (lower, upper): in tolerance only green to yellow
    (cyan) at |d| = max(|lower|, |upper|); above upper red, below lower blue. Without: green ->
    yellow at scale / 2 -> red at scale (and beyond)."""
    warm = (YELLOW, RED) if d >= 0 else (CYAN, BLUE)
    if band is not None:
        lower, upper = band
        if d > upper:
            return RED
        if d < lower:
            return BLUE
        half = max(abs(lower), abs(upper))
        return _mix(GREEN, warm[0], min(abs(d) / half, 1.0)) if half > 0 else GREEN
    f = min(abs(d) / scale, 1.0) if scale > 0 else 0.0
    return _mix(GREEN, warm[0], 2 * f) if f <= 0.5 else _mix(warm[0], warm[1], 2 * f - 1)


def _number(value, what):
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise CaptureError("%s must be a number, not %r" % (what, value))
    return float(value)


def band_of(entry, what):
    """(lower, upper) from an entry's "lower"/"upper" or "tolerance" (t = +-t, [lower, upper]); None without."""
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


def read_report(source):
    """The inspection JSON (a path or the parsed dict): a list of points, each
    {"feature", "xyz", "deviation", "band"}, the band from the point itself or else from the
    first characteristic naming its feature that carries a tolerance."""
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
                           "{\"points\": [{\"feature\": NAME, \"xyz\": [x, y, z], \"deviation\": d}, ...]}" % name)
    feature_bands = {}
    for i, c in enumerate(report.get("characteristics") or []):
        if isinstance(c, dict) and isinstance(c.get("feature"), str) and c["feature"] not in feature_bands:
            band = band_of(c, "%s characteristic %d" % (name, i + 1))
            if band is not None:
                feature_bands[c["feature"]] = band
    out = []
    for i, p in enumerate(points):
        what = "%s point %d" % (name, i + 1)
        xyz = p.get("xyz") if isinstance(p, dict) else None
        if not isinstance(xyz, list) or len(xyz) != 3:
            raise CaptureError("%s: \"xyz\" must be [x, y, z], not %r" % (what, xyz))
        feature = str(p.get("feature", ""))
        band = band_of(p, what) or feature_bands.get(feature)
        out.append({"feature": feature, "xyz": FreeCAD.Vector(*(_number(v, what + " xyz") for v in xyz)),
                    "deviation": _number(p.get("deviation"), what + " deviation"), "band": band})
    return out


def _set(obj, ptype, name, doc_text, value):
    if name not in obj.PropertiesList:
        obj.addProperty(ptype, name, _PROPERTY_GROUP, doc_text)
    setattr(obj, name, value)


def _clear(obj):
    for name in _PROPERTIES:
        if name in obj.PropertiesList:
            obj.removeProperty(name)
    if FreeCAD.GuiUp:
        obj.ViewObject.PointColor = CAPTURED_COLOUR


def colour_points(doc, source):
    """Colours the captured point at each inspected point's xyz (within MATCH_MM), or adds a point
    to IMESS_Deviations when none was captured there. Colours of an earlier report are replaced.
    Returns a summary: points, matched, added, out_of_tolerance, scale (the +- range without a band)."""
    points = read_report(source)
    scale = max([abs(p["deviation"]) for p in points] + [0.0])
    old = doc.getObject(DEVIATION_GROUP)
    if old is not None:
        for o in list(old.Group):
            doc.removeObject(o.Name)
    captured = doc.getObject(POINT_GROUP)
    candidates = [o for o in (captured.Group if captured is not None else []) if hasattr(o, "Measured")]
    for o in candidates:
        if "Deviation" in o.PropertiesList:
            _clear(o)
    summary = {"points": len(points), "matched": 0, "added": 0, "out_of_tolerance": 0, "scale": scale}
    for p in points:
        obj = min(candidates, key=lambda o: (o.Measured - p["xyz"]).Length, default=None)
        if obj is not None and (obj.Measured - p["xyz"]).Length <= MATCH_MM and "Deviation" not in obj.PropertiesList:
            summary["matched"] += 1
        else:
            obj = doc.addObject("Part::Feature", "Deviation")
            obj.Shape = Part.Vertex(p["xyz"])
            document_group(doc, DEVIATION_GROUP, "IMESS deviations").addObject(obj)
            summary["added"] += 1
        d, band = p["deviation"], p["band"]
        colour = deviation_colour(d, scale, band)
        _set(obj, "App::PropertyFloat", "Deviation", "deviation from the plan's nominal (mm)", d)
        _set(obj, "App::PropertyString", "Feature", "the plan's feature this point belongs to", p["feature"])
        if band is not None:
            _set(obj, "App::PropertyFloat", "ToleranceLower", "lowest deviation in tolerance (mm)", band[0])
            _set(obj, "App::PropertyFloat", "ToleranceUpper", "highest deviation in tolerance (mm)", band[1])
            inside = band[0] <= d <= band[1]
            _set(obj, "App::PropertyBool", "InTolerance", "deviation within [lower, upper]", inside)
            summary["out_of_tolerance"] += 0 if inside else 1
        _set(obj, "App::PropertyColor", "DeviationColor", "the colour shown for the deviation", colour)
        if obj.Label.startswith("Deviation"):
            obj.Label = "%s %+.4f" % (p["feature"] or "point", d)
        if FreeCAD.GuiUp:
            obj.ViewObject.PointColor = colour
            obj.ViewObject.PointSize = 8
    doc.recompute()
    return summary


def run_inspect(plan, points, messcap=None):
    """`messcap inspect PLAN --points FILE --json OUT` on the given points; returns OUT's path."""
    if not os.path.isfile(plan):
        raise CaptureError("inspection plan %s not found" % plan)
    exe = messcap or find_messcap()
    work = tempfile.mkdtemp(prefix="imess-inspect-")
    points_path, out_path = os.path.join(work, "points.xyz"), os.path.join(work, "inspection.json")
    with open(points_path, "w") as f:
        f.write(xyz_text(points))
    r = subprocess.run([exe, "inspect", plan, "--points", points_path, "--json", out_path],
                       capture_output=True, text=True, timeout=60)
    if not os.path.isfile(out_path):  # a report with characteristics out of tolerance is still a report
        raise CaptureError(r.stderr.strip() or "messcap inspect wrote no report (exit %d)" % r.returncode)
    return out_path
