"""messcap's QIF results, offline: the worked-example cube inspected from points (one face 0.1 mm
off, so one characteristic FAILs) with --qif, a saved report converted, two reports in one
document — each valid against the QIF 3.0 schemas and equal, figure by figure, to its JSON report;
bad input refused with a clear message; and mutated documents (a wrong status word, a missing
required element, a dangling id reference, a changed value) caught — so the checks bite.

    test_qif.py MESSCAP SOURCE_DIR
"""
import json
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import qif_check  # noqa: E402

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run(*args):
    return subprocess.run(list(args), capture_output=True, text=True, timeout=60)


def cube_points(plan, path, shift_right):
    """The plan's probe points on the nominal cube, machine coordinates (placement + (400, 300, 0)),
    the right face `shift_right` mm further out."""
    with open(path, "w") as f:
        for feature in plan["features"]:
            shift = shift_right if feature["name"] == "right" else 0.0
            for p in feature["probe"]:
                f.write(f"{feature['name']} {p[0] + 400 + shift} {p[1] + 300} {p[2]}\n")


def every_kind_report():
    """A report as messcap inspect --json writes it, with every feature kind (and a feature whose fit
    failed) and every characteristic kind (and one not evaluated): the writer's every branch."""
    def feature(name, nominal, actual=None, n=3):
        f = {"name": name, "points": n, "nominal": nominal}
        if actual:
            f.update(actual=actual, compensated=True, form=0.0012, rms=0.0004)
        else:
            f["error"] = "circle fit needs 3 points, got 2"
        return f
    pl = lambda z: {"type": "plane", "point": [0, 0, z], "normal": [0, 0, 1]}  # noqa: E731
    features = [
        feature("p", {"type": "point", "point": [10, 0, 5], "normal": [1, 0, 0]},
                {"type": "point", "point": [10.002, 0, 5], "normal": [1, 0, 0]}, 1),
        feature("l", {"type": "line", "point": [0, 0, 5], "direction": [1, 0, 0]},
                {"type": "line", "point": [0, 0.001, 5], "direction": [1, 0, 0]}),
        feature("base", pl(0), pl(0.001), 4),
        feature("top", pl(20), pl(20.003), 4),
        feature("c", {"type": "circle", "center": [30, 30, 20], "normal": [0, 0, 1], "diameter": 10, "inner": True},
                {"type": "circle", "center": [30.001, 30, 20], "normal": [0, 0, 1], "diameter": 10.004, "inner": True}),
        feature("s", {"type": "sphere", "center": [50, 50, 30], "diameter": 25, "inner": False},
                {"type": "sphere", "center": [50, 50.002, 30], "diameter": 24.998, "inner": False}, 5),
        feature("cy", {"type": "cylinder", "point": [30, 30, 0], "axis": [0, 0, 1], "diameter": 10, "inner": True},
                {"type": "cylinder", "point": [30, 30, 0], "axis": [0, 0, 1], "diameter": 10.003, "inner": True}, 6),
        feature("co", {"type": "cone", "point": [70, 0, 0], "axis": [0, 0, 1], "diameter": 20, "apex_angle_deg": 60,
                       "inner": False},
                {"type": "cone", "point": [70, 0, 0], "axis": [0, 0, 1], "diameter": 20.01, "apex_angle_deg": 60.02,
                 "inner": False}, 6),
        feature("broken", {"type": "circle", "center": [0, 50, 20], "normal": [0, 0, 1], "diameter": 8, "inner": True},
                None, 2),
    ]

    def char(name, kind, feature, lower, upper, actual, other=None, unit="mm", **extra):
        zone = kind not in ("size", "distance", "angle")
        c = {"name": name, "type": kind, "feature": feature, "unit": unit, "zone": zone, "lower": lower, "upper": upper}
        if other:
            c["datum" if kind in ("perpendicularity", "parallelism") else "other"] = other
        c.update(extra)
        if actual is None:
            c["error"] = "feature 'broken' has no fit"
        else:
            nominal = extra.pop("nominal_value", 0.0)
            c.pop("nominal_value", None)
            dev = actual if zone else actual - nominal
            c.update(nominal=nominal, actual=actual, deviation=round(dev, 9), in_tolerance=lower <= dev <= upper)
        return c
    chars = [
        char("s dia", "size", "s", -0.01, 0.01, 24.998, nominal_value=25),
        char("c radius", "size", "c", -0.01, 0.01, 5.002, nominal_value=5, radius=True),
        char("co dia", "size", "co", -0.005, 0.005, 20.01, nominal_value=20),
        char("p pos", "position", "p", 0, 0.01, 0.004),
        char("l pos", "position", "l", 0, 0.01, 0.002),
        char("s pos", "position", "s", 0, 0.01, 0.004),
        char("cy pos", "position", "cy", 0, 0.01, 0.0),
        char("p-base", "distance", "p", -0.05, 0.05, 5.001, other="base", nominal_value=5),
        char("l-base angle", "angle", "l", -0.1, 0.1, 0.02, other="base", unit="deg", nominal_value=0),
        char("base flat", "flatness", "base", 0, 0.01, 0.0012),
        char("c round", "roundness", "c", 0, 0.01, 0.0012),
        char("cy cyl", "cylindricity", "cy", 0, 0.01, 0.0012),
        char("s sph", "sphericity", "s", 0, 0.01, 0.0009),
        char("cy perp", "perpendicularity", "cy", 0, 0.01, 0.003, other="base"),
        char("l perp", "perpendicularity", "l", 0, 0.01, 0.003, other="cy"),
        char("top par", "parallelism", "top", 0, 0.01, 0.002, other="base"),
        char("co par", "parallelism", "co", 0, 0.01, 0.002, other="cy"),
        char("broken dia", "size", "broken", -0.01, 0.01, None),
    ]
    points = []
    for f in features:
        for k in range(f["points"]):
            points.append({"feature": f["name"], "xyz": [k, 2 * k, 3.5], "deviation": 0.001 * k,
                           "machine": [k + 400, 2 * k + 300, 3.5], "approach": [0, 0, -1], "radius": 1.5})
    out = sum(1 for c in chars if "actual" in c and not c["in_tolerance"])
    return {"part": "every-kind", "plan": "every-kind.plan.json", "measured": "points from every-kind.txt",
            "time": "2026-11-29T10:00:00Z", "units": {"length": "mm", "angle": "deg"},
            "alignment": {"from": "alignment", "datums": ["base", "l", "p"]},
            "characteristics": chars, "features": features, "points": points,
            "summary": {"characteristics": len(chars), "in_tolerance": len(chars) - out - 1,
                        "out_of_tolerance": out, "not_evaluated": 1}}


def main(messcap, source):
    t0 = time.monotonic()
    tmp = tempfile.TemporaryDirectory(prefix="imess-qif-")
    d = tmp.name
    f = lambda name: os.path.join(d, name)  # noqa: E731
    plan_path = os.path.join(source, "examples", "cube-1996.plan.json")
    with open(plan_path) as fp:
        plan = json.load(fp)
    cube_points(plan, f("off.txt"), 0.1)
    cube_points(plan, f("good.txt"), 0.0)

    # 1. inspect --points … --qif: the operator's name has characters XML must escape.
    operator = "J. Smith & Söhne <QA>"
    r = run(messcap, "inspect", plan_path, "--points", f("off.txt"), "--json", f("off.json"), "--qif", f("off.qif"),
            "--operator", operator)
    check(r.returncode == 5, f"inspect --qif of the cube with its right face 0.1 mm out exits 5 (got {r.returncode}: {r.stderr})")
    r = run(messcap, "inspect", plan_path, "--points", f("good.txt"), "--json", f("good.json"), "--qif", f("good.qif"))
    check(r.returncode == 0, f"inspect --qif of the nominal cube exits 0 (got {r.returncode}: {r.stderr})")
    # --qif - writes the document to stdout (the table goes to stderr).
    r = run(messcap, "inspect", plan_path, "--points", f("good.txt"), "--qif", "-")
    check(r.returncode == 0 and r.stdout.startswith("<?xml") and "13 characteristics" in r.stderr,
          "inspect --qif - writes the document to stdout, the table to stderr")
    with open(f("stdout.qif"), "w") as fp:
        fp.write(r.stdout)

    # 2. convert: one saved report, and two runs of the plan in one document.
    r = run(messcap, "convert", f("off.json"), f("converted.qif"))
    check(r.returncode == 0 and "1 inspection run written" in r.stderr, f"convert REPORT.json OUT.qif ({r.stderr.strip()})")
    r = run(messcap, "convert", f("off.json"), f("good.json"), f("two.qif"))
    check(r.returncode == 0 and "2 inspection runs written" in r.stderr, f"convert of two reports ({r.stderr.strip()})")

    # Every feature and characteristic kind, a failed fit, a characteristic not evaluated.
    with open(f("every.json"), "w") as fp:
        json.dump(every_kind_report(), fp, indent=1)
    r = run(messcap, "convert", f("every.json"), f("every.qif"))
    check(r.returncode == 0, f"convert of a report with every feature and characteristic kind ({r.stderr.strip()})")

    written = [f("off.qif"), f("good.qif"), f("stdout.qif"), f("converted.qif"), f("two.qif"), f("every.qif")]
    t1 = time.monotonic()
    verdict = qif_check.validate(source, written)
    t_validate = time.monotonic() - t1
    for p in written:
        check(verdict[p] is None, f"{os.path.basename(p)} validates against the QIF 3.0 schemas {verdict[p] or ''}")
    pairs = [(f("off.qif"), [f("off.json")]), (f("good.qif"), [f("good.json")]), (f("converted.qif"), [f("off.json")]),
             (f("two.qif"), [f("off.json"), f("good.json")]), (f("every.qif"), [f("every.json")])]
    for qif, reports in pairs:
        try:
            qif_check.compare(qif, reports)
            check(True, f"{os.path.basename(qif)}: every characteristic, feature and point equals the JSON report's")
        except qif_check.QifMismatch as e:
            check(False, str(e))

    # What the comparison read, spelled out for the cube: the length FAILs, the rest PASS.
    root = qif_check.ET.parse(f("off.qif")).getroot()
    ns = qif_check.NS
    ids = {int(e.attrib["id"]): e for e in root.iter() if "id" in e.attrib}
    statuses = {}
    for m in root.iter():
        if m.tag.endswith("CharacteristicMeasurement"):
            name = ids[int(m.find(ns + "CharacteristicItemId").text)].find(ns + "Name").text
            statuses[name] = (m.find(f"{ns}Status/{ns}CharacteristicStatusEnum").text, float(m.find(ns + "Value").text))
    check(statuses.get("length") == ("FAIL", 120.1), f"length: FAIL, 120.1 mm ({statuses.get('length')})")
    check(len(statuses) == 13 and sum(s == "PASS" for s, _ in statuses.values()) == 12, "the other 12 characteristics PASS")
    check(root.find(f"{ns}Results/{ns}MeasurementResultsSet/{ns}MeasurementResults/{ns}InspectionStatus/"
                    f"{ns}InspectionStatusEnum").text == "FAIL", "the run's InspectionStatus is FAIL")
    check(root.find(f".//{ns}InspectionOperator/{ns}Name").text == operator, "the operator's name, escaped and read back")
    two = qif_check.ET.parse(f("two.qif")).getroot()
    check([e.text for e in two.iter(ns + "InspectionStatusEnum")] == ["FAIL", "PASS"],
          "two runs in one document: FAIL, then PASS")

    # 3. Bad input: a clear error, nothing written.
    with open(f("other.json"), "w") as fp:
        other = json.load(open(f("good.json")))
        other["characteristics"][0]["upper"] = 0.5
        json.dump(other, fp)
    r = run(messcap, "convert", f("off.json"), f("other.json"), f("mixed.qif"))
    check(r.returncode == 1 and "is not a run of the plan of" in r.stderr and "characteristic 1 ('length') differs" in r.stderr
          and not os.path.exists(f("mixed.qif")), f"reports of different plans refused ({r.stderr.strip()})")
    with open(f("bad.json"), "w") as fp:
        bad = json.load(open(f("good.json")))
        bad["characteristics"][3]["actual"] = "30"
        json.dump(bad, fp)
    r = run(messcap, "convert", f("bad.json"), f("bad.qif"))
    check(r.returncode == 1 and "bad.json: characteristics[3].actual: expected a number" in r.stderr
          and not os.path.exists(f("bad.qif")), f"a bad report named by key ({r.stderr.strip()})")
    with open(f("moved.json"), "w") as fp:
        moved = json.load(open(f("good.json")))
        moved["features"][4]["nominal"]["point"][0] += 1.0
        json.dump(moved, fp)
    r = run(messcap, "convert", f("good.json"), f("moved.json"), f("mixed.qif"))
    check(r.returncode == 1 and f"feature '{moved['features'][4]['name']}' has another nominal geometry" in r.stderr,
          f"a report whose plan moved a feature refused ({r.stderr.strip()})")
    r = run(messcap, "inspect", plan_path, "--points", f("good.txt"), "--json", "-", "--qif", "-")
    check(r.returncode == 2 and "both want stdout" in r.stderr, "--json - and --qif - together refused")
    r = run(messcap, "convert", f("off.json"), f("off.qif"))
    check(r.returncode == 1 and "exists; add --force" in r.stderr, "an existing QIF is not replaced without --force")
    r = run(messcap, "convert", f("off.json"), f("off.qif"), "--force")
    check(r.returncode == 0, "... and is with --force")

    # 4. Mutations the checks must catch.
    with open(f("off.qif")) as fp:
        text = fp.read()
    mutants = {
        "a wrong status word": text.replace("<CharacteristicStatusEnum>FAIL<", "<CharacteristicStatusEnum>FAILED<", 1),
        "a missing required element": re.sub(r"\s*<CharacteristicItemId>\d+</CharacteristicItemId>", "", text, count=1),
        "a dangling id reference": re.sub(r"<FeatureItemId>\d+<", "<FeatureItemId>99999<", text, count=1),
    }
    paths = []
    for k, (what, mutant) in enumerate(mutants.items()):
        check(mutant != text, f"mutation made: {what}")
        paths.append(f(f"mutant{k}.qif"))
        with open(paths[-1], "w") as fp:
            fp.write(mutant)
    verdict = qif_check.validate(source, paths)
    for what, p in zip(mutants, paths):
        check(verdict[p] is not None, f"{what} fails the schema check: {(verdict[p] or '').splitlines()[:1]}")
    # A value changed within the schema's rules: valid, but no longer the report's.
    changed = f("changed.qif")
    with open(changed, "w") as fp:
        fp.write(text.replace("<Value>120.1</Value>", "<Value>120.2</Value>", 1))
    check(qif_check.validate(source, [changed])[changed] is None, "a changed value still validates")
    try:
        qif_check.compare(changed, [f("off.json")])
        check(False, "a changed value is caught by the comparison")
    except qif_check.QifMismatch as e:
        check("'length' Value 120.2" in str(e), f"a changed value is caught by the comparison ({e})")

    print(f"schema check of {len(written)} documents in one xmllint call: {t_validate:.2f} s; "
          f"whole test {time.monotonic() - t0:.2f} s")
    print(f"{len(failures)} failed" if failures else "all QIF checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
