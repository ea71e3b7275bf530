# Inside freecadcmd: reads point files the way FreeCAD does and writes what it found as JSON.
# argv: OUT.json FILE... — .stp/.igs through Part.Shape.read and Import.insert (File > Import),
# .ply/.asc through Points.insert.
import json
import os
import sys

import FreeCAD
import Import
import Part
import Points


def read(path):
    ext = os.path.splitext(path)[1].lower()
    found = {}
    if ext in (".stp", ".igs"):
        shape = Part.Shape()
        shape.read(path)
        found["Part.Shape.read"] = [list(v.Point) for v in shape.Vertexes]
        doc = FreeCAD.newDocument("import_" + ext[1:])
        Import.insert(path, doc.Name)
        found["Import.insert"] = [list(v.Point) for o in doc.Objects if hasattr(o, "Shape") for v in o.Shape.Vertexes]
        FreeCAD.closeDocument(doc.Name)
    else:
        doc = FreeCAD.newDocument("points_" + ext[1:])
        Points.insert(path, doc.Name)
        found["Points.insert"] = [list(p) for o in doc.Objects for p in o.Points.Points]
        FreeCAD.closeDocument(doc.Name)
    return found


try:
    result = {path: read(path) for path in sys.argv[2:]}
    with open(sys.argv[1], "w") as f:
        json.dump(result, f)
except Exception as e:  # noqa: BLE001 - report anything, exit non-zero
    print("freecad_read_points: %s: %s" % (type(e).__name__, e), file=sys.stderr)
    os._exit(1)
os._exit(0)
