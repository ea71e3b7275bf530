"""QIF documents written by messcap, checked independently of messcap's code: validity against
the QIF 3.0 schemas (xmllint, Debian's libxml2-utils, all files in one call), every id reference
resolving, and every figure equal to the JSON report the run also wrote (read with Python's own
XML parser). Used by test_qif.py and, as a program, by the live cube test:

    qif_check.py SOURCE_DIR QIF REPORT.json [REPORT.json ...]

(one report per MeasurementResults, in order). Exit 0 when everything holds, else 1 with the
reasons on stderr.
"""
import json
import math
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

NS = "{http://qifstandards.org/xsd/qif3}"
STATUS = {True: "PASS", False: "FAIL"}


class QifMismatch(Exception):
    pass


def schema_path(source):
    return os.path.join(source, "tests", "data", "qif", "QIFApplications", "QIFDocument.xsd")


def validate(source, paths):
    """xmllint's verdict on each file: {path: None if valid, else the error text}."""
    xmllint = shutil.which("xmllint")
    if xmllint is None:
        raise SystemExit("xmllint is missing: install Debian's libxml2-utils (scripts/deps.sh does)")
    run = subprocess.run([xmllint, "--noout", "--schema", schema_path(source), *paths],
                         capture_output=True, text=True, timeout=60)
    verdict = {}
    for p in paths:
        if f"{p} validates" in run.stderr:
            verdict[p] = None
        else:
            verdict[p] = "\n".join(line for line in run.stderr.splitlines() if line.startswith(p)) or run.stderr
    return verdict


def local(tag):
    return tag[len(NS):] if tag.startswith(NS) else tag


def numbers(text):
    return [float(x) for x in text.split()]


def close(a, b, tol=2e-6):
    return abs(a - b) <= tol


def check_ids(root):
    """Every id unique, idMax not below any, every reference (…Id elements, Id list entries)
    naming an element of the document."""
    ids = {}
    for e in root.iter():
        if "id" in e.attrib:
            i = int(e.attrib["id"])
            if i in ids:
                raise QifMismatch(f"id {i} given twice ({local(ids[i].tag)}, {local(e.tag)})")
            ids[i] = e
    if ids and int(root.attrib["idMax"]) < max(ids):
        raise QifMismatch(f"idMax {root.attrib['idMax']} below the largest id {max(ids)}")
    for e in root.iter():
        name = local(e.tag)
        if (name.endswith("Id") and name not in ("QPId",)) or name == "Id":
            ref = int(e.text)
            if ref not in ids:
                raise QifMismatch(f"{name} {ref} refers to no element")
    return ids


def child(e, name):
    c = e.find(NS + name)
    if c is None:
        raise QifMismatch(f"{local(e.tag)} id {e.attrib.get('id')} has no {name}")
    return c


def compare_run(results, report, ids, where):
    """One MeasurementResults against its JSON report."""
    chars = {c["name"]: c for c in report["characteristics"]}
    features = {f["name"]: f for f in report["features"]}
    measured = results.find(NS + "MeasuredCharacteristics")
    seen = set()
    for m in (measured.find(NS + "CharacteristicMeasurements") if measured is not None else []):
        item = ids[int(child(m, "CharacteristicItemId").text)]
        name = child(item, "Name").text
        c = chars.get(name)
        if c is None:
            raise QifMismatch(f"{where}: characteristic '{name}' is not in the report")
        seen.add(name)
        status = child(child(m, "Status"), "CharacteristicStatusEnum").text
        if "actual" in c:
            value = float(child(m, "Value").text)
            if not close(value, c["actual"]):
                raise QifMismatch(f"{where}: '{name}' Value {value}, the report's actual {c['actual']}")
            dev = [a for a in m.iter(NS + "AttributeD1") if a.attrib["name"] == "deviation"]
            if len(dev) != 1 or not close(float(dev[0].attrib["value"]), c["deviation"]):
                raise QifMismatch(f"{where}: '{name}' deviation is not the report's {c['deviation']}")
            if status != STATUS[c["in_tolerance"]]:
                raise QifMismatch(f"{where}: '{name}' status {status}, the report says in_tolerance {c['in_tolerance']}")
        elif status != "INDETERMINATE":
            raise QifMismatch(f"{where}: '{name}' was not evaluated, yet its status is {status}")
        # The plan's side: the nominal and the limits this measurement's item stands for.
        nominal = ids[int(child(item, "CharacteristicNominalId").text)]
        definition = ids[int(child(nominal, "CharacteristicDefinitionId").text)]
        if c["zone"]:
            if not close(float(child(definition, "ToleranceValue").text), c["upper"]):
                raise QifMismatch(f"{where}: '{name}' ToleranceValue is not the report's {c['upper']}")
        else:
            tol = child(definition, "Tolerance")
            if not (close(float(child(tol, "MaxValue").text), c["upper"]) and
                    close(float(child(tol, "MinValue").text), c["lower"])):
                raise QifMismatch(f"{where}: '{name}' limits are not the report's {c['lower']}/{c['upper']}")
            if "nominal" in c and not close(float(child(nominal, "TargetValue").text), c["nominal"]):
                raise QifMismatch(f"{where}: '{name}' TargetValue is not the report's nominal {c['nominal']}")
    if seen != set(chars):
        raise QifMismatch(f"{where}: characteristics {sorted(set(chars) - seen)} missing")

    point_sets = {}
    sets = results.find(NS + "MeasuredPointSets")
    for s in (sets if sets is not None else []):
        point_sets[int(s.attrib["id"])] = s
    fseen = set()
    for m in child(results, "MeasuredFeatures"):
        item = ids[int(child(m, "FeatureItemId").text)]
        name = child(item, "FeatureName").text
        f = features[name]
        fseen.add(name)
        actual = f.get("actual")
        if actual is not None:
            centre = actual.get("center", actual.get("point"))
            loc = m.find(NS + "Location")
            if loc is None:
                loc = child(child(m, "Axis"), "AxisPoint")
            if not all(close(a, b) for a, b in zip(numbers(loc.text), centre)):
                raise QifMismatch(f"{where}: feature '{name}' at {loc.text}, the report's actual at {centre}")
            if "diameter" in actual and not close(float(child(m, "Diameter").text), actual["diameter"]):
                raise QifMismatch(f"{where}: feature '{name}' diameter is not the report's {actual['diameter']}")
        points = [p for p in report["points"] if p["feature"] == name]
        plist = m.find(NS + "PointList")
        if points:
            s = point_sets[int(child(plist, "WholePointSetId").text)]
            xyz = numbers(child(s, "Points").text)
            if int(s.attrib["count"]) != len(points) or len(xyz) != 3 * len(points):
                raise QifMismatch(f"{where}: feature '{name}' has {s.attrib['count']} points, the report {len(points)}")
            for k, p in enumerate(points):
                if not all(close(a, b) for a, b in zip(xyz[3 * k:3 * k + 3], p["xyz"])):
                    raise QifMismatch(f"{where}: point {k + 1} of '{name}' is not the report's {p['xyz']}")
    if fseen != set(features):
        raise QifMismatch(f"{where}: features {sorted(set(features) - fseen)} missing")

    expected = ("FAIL" if report["summary"]["out_of_tolerance"] else
                "NOT_CALCULATED" if report["summary"]["not_evaluated"] else "PASS")
    status = child(child(results, "InspectionStatus"), "InspectionStatusEnum").text
    if status != expected:
        raise QifMismatch(f"{where}: InspectionStatus {status}, expected {expected}")
    trace = results.find(NS + "InspectionTraceability")
    if "operator" in report:
        op = trace.find(f"{NS}InspectionOperator/{NS}Name") if trace is not None else None
        if op is None or op.text != report["operator"]:
            raise QifMismatch(f"{where}: operator is not the report's '{report['operator']}'")
    if "time" in report and (trace is None or child(trace, "InspectionStart").text != report["time"]):
        raise QifMismatch(f"{where}: InspectionStart is not the report's time {report['time']}")


def compare(qif_path, report_paths):
    root = ET.parse(qif_path).getroot()
    ids = check_ids(root)
    runs = root.findall(f"{NS}Results/{NS}MeasurementResultsSet/{NS}MeasurementResults")
    if len(runs) != len(report_paths):
        raise QifMismatch(f"{qif_path}: {len(runs)} MeasurementResults for {len(report_paths)} reports")
    for k, (results, rp) in enumerate(zip(runs, report_paths)):
        with open(rp) as f:
            compare_run(results, json.load(f), ids, f"{qif_path} run {k + 1} ({os.path.basename(rp)})")
    return root


def main(argv):
    if len(argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    source, qif, reports = argv[1], argv[2], argv[3:]
    error = validate(source, [qif])[qif]
    if error:
        print(f"{qif} is not valid QIF 3.0:\n{error}", file=sys.stderr)
        return 1
    try:
        compare(qif, reports)
    except QifMismatch as e:
        print(str(e), file=sys.stderr)
        return 1
    print(f"{qif}: valid QIF 3.0, every figure the report's")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
