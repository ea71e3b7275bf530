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

    written = [f("off.qif"), f("good.qif"), f("stdout.qif"), f("converted.qif"), f("two.qif")]
    t1 = time.monotonic()
    verdict = qif_check.validate(source, written)
    t_validate = time.monotonic() - t1
    for p in written:
        check(verdict[p] is None, f"{os.path.basename(p)} validates against the QIF 3.0 schemas {verdict[p] or ''}")
    pairs = [(f("off.qif"), [f("off.json")]), (f("good.qif"), [f("good.json")]), (f("converted.qif"), [f("off.json")]),
             (f("two.qif"), [f("off.json"), f("good.json")])]
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
