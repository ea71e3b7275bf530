# messcap's export formats read back by independent readers: DXF by ezdxf, STEP/IGES/PLY/ASC
# by FreeCAD (freecadcmd). Points are generated, written with `messcap convert`, read, compared.
"""usage: readback_exports.py ezdxf|freecad MESSCAP"""
import json
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, HERE)
import run_in_freecad  # noqa: E402


def make_points(n=37, seed=1996):
    """Millimetres with three decimals as messd sends them: negative, small, near 1000."""
    rnd = random.Random(seed)
    pts = [(round(rnd.uniform(-999, 999), 3), round(rnd.uniform(-50, 50), 3), round(rnd.uniform(0, 600), 3))
           for _ in range(n)]
    pts[0] = (0.0, 0.0, 0.0)
    pts[1] = (430.125, 330.0, 80.0)
    return pts


def convert(messcap, directory, points, ext):
    src = os.path.join(directory, "in.xyz")
    with open(src, "w") as f:
        f.writelines("%.3f %.3f %.3f\n" % p for p in points)
    out = os.path.join(directory, "points" + ext)
    r = subprocess.run([messcap, "convert", src, out, "--decimals", "3"], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("messcap convert %s failed (%d): %s" % (ext, r.returncode, r.stderr))
    return out


def compare(label, expected, got, tolerance):
    """Same count, and each expected point found (order-free) within tolerance(value)."""
    if len(got) != len(expected):
        return ["%s: %d points read, %d written" % (label, len(got), len(expected))]
    errors = []
    for e, g in zip(sorted(expected), sorted(tuple(p) for p in got)):
        if any(abs(a - b) > tolerance(a) for a, b in zip(e, g)):
            errors.append("%s: point %s read as %s" % (label, e, g))
    return errors[:5]


def exact(_):
    return 1e-9


def single_precision(v):  # FreeCAD's Points kernel keeps float32 coordinates
    return abs(v) * 1.2e-7 + 1e-9


def check_ezdxf(messcap, directory, points):
    try:
        import ezdxf
    except ImportError:
        sys.exit("python3 module ezdxf missing: install the Debian package python3-ezdxf (scripts/test does)")
    path = convert(messcap, directory, points, ".dxf")
    doc = ezdxf.readfile(path)
    errors = []
    if doc.dxfversion != "AC1009":
        errors.append("DXF version %s, expected AC1009 (R12)" % doc.dxfversion)
    auditor = doc.audit()
    errors += ["ezdxf audit: %s" % e.message for e in auditor.errors]
    entities = list(doc.modelspace())
    if any(e.dxftype() != "POINT" for e in entities):
        errors.append("entities other than POINT: %s" % sorted({e.dxftype() for e in entities}))
    if any(e.dxf.layer != "IMESS_POINTS" for e in entities):
        errors.append("a POINT not on layer IMESS_POINTS")
    if "IMESS_POINTS" not in doc.layers:
        errors.append("layer IMESS_POINTS not in the LAYER table")
    errors += compare("DXF", points, [tuple(e.dxf.location) for e in entities], exact)
    return errors


def check_freecad(messcap, directory, points):
    files = [convert(messcap, directory, points, ext) for ext in (".stp", ".igs", ".ply", ".asc")]
    out = os.path.join(directory, "read.json")
    status = run_in_freecad.run(os.path.join(HERE, "freecad_read_points.py"), [out] + files)
    if status != 0:
        return ["freecadcmd reader exited with %d" % status]
    with open(out) as f:
        found = json.load(f)
    errors = []
    for path in files:
        for reader, got in found[path].items():
            tol = single_precision if reader == "Points.insert" else exact
            errors += compare("%s via %s" % (os.path.basename(path), reader), points, got, tol)
            print("%s via %s: %d points" % (os.path.basename(path), reader, len(got)))
    return errors


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("ezdxf", "freecad"):
        sys.exit(__doc__)
    points = make_points()
    with tempfile.TemporaryDirectory(prefix="imess-readback-") as directory:
        check = check_ezdxf if sys.argv[1] == "ezdxf" else check_freecad
        errors = check(sys.argv[2], directory, points)
    for e in errors:
        print("FAIL " + e, file=sys.stderr)
    if not errors:
        print("%s: all %d points read back" % (sys.argv[1], len(points)))
    sys.exit(1 if errors else 0)


if __name__ == "__main__":
    main()
