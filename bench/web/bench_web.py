#!/usr/bin/python3
"""bench_web: the web panel's browser path against the line protocol's push, in the same run.
A real messd (release build from scripts/bench) and a real Chromium showing its panel; a line
client on 1066 sends ForcePt N times. For each point: the Hit line's arrival on 1066 after the
ForcePt was sent (the line protocol's push) and its row's appearance in the page's list after
the same send (the browser path: messd's web front end, the WebSocket, the page's JavaScript,
the DOM). Both stamped with one clock (the page's wall clock brought to time.monotonic()).
Writes bench_web.json in the figures format of bench/report.py (docs/performance.md).

Usage: bench_web.py --messd PATH --config FILE --json OUT [--points N]
"""
import argparse
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import time

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.by import By
except ImportError:
    sys.exit("bench_web: python3-selenium is missing (apt-get install python3-selenium chromium chromium-driver)")


def percentile(values, p):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(p / 100.0 * (len(ordered) - 1))))]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--messd", required=True)
    ap.add_argument("--config", required=True)
    ap.add_argument("--json", required=True)
    ap.add_argument("--points", type=int, default=200)
    args = ap.parse_args()

    work = tempfile.mkdtemp(prefix="imess-bench-web-")
    messd = subprocess.Popen([args.messd, "--port", "0", "--listen", "127.0.0.1", "--no-rt", "--config", args.config,
                              "--journal", os.path.join(work, "journal"), "--frames", os.path.join(work, "frames.json")],
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    driver = None
    try:
        lines = [messd.stdout.readline() for _ in range(3)]
        port = int(re.search(r":(\d+)$", lines[0].strip()).group(1))
        url = re.search(r"web panel on (http://[\d.]+:\d+/)", lines[2]).group(1)
        options = webdriver.ChromeOptions()
        options.binary_location = "/usr/bin/chromium"
        for a in ("--headless=new", "--no-sandbox", "--window-size=1024,768", "--disable-dev-shm-usage",
                  "--user-data-dir=" + os.path.join(work, "chromium")):
            options.add_argument(a)
        driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
        driver.get(url)
        deadline = time.time() + 20
        while driver.find_element(By.ID, "link").text != "online":
            if time.time() > deadline:
                sys.exit("bench_web: the page did not connect to messd")
            time.sleep(0.05)
        line = socket.create_connection(("127.0.0.1", port), timeout=10)
        reader = line.makefile("r", encoding="ascii", newline="\n")
        line.sendall(b"Hello bench_web\n")
        push_ms, row_ms = [], []
        sent_at = {}
        for _ in range(args.points):
            sent = time.monotonic()
            line.sendall(b"ForcePt\n")
            while True:  # the Hit line, then the reply
                text = reader.readline()
                if not text:
                    sys.exit("bench_web: messd closed the line connection")
                if text.startswith("Hit "):
                    push_ms.append((time.monotonic() - sent) * 1000)
                    sent_at[int(text.split()[1])] = sent
                if text.startswith("Err"):
                    sys.exit("bench_web: ForcePt refused: " + text.strip())
                if text.startswith("Ok ForcePt") and len(push_ms) == len(sent_at) and sent_at:
                    break
            time.sleep(0.02)  # one point at a time: each measured unloaded by the others
        offset = time.time() - time.monotonic()
        deadline = time.time() + 10
        rows = []
        while time.time() < deadline:
            rows = driver.execute_script(
                "return [...document.querySelectorAll('#points tbody tr')].map(r => [Number(r.dataset.seq), Number(r.dataset.shownAt)]);")
            if sum(1 for seq, _ in rows if seq in sent_at) >= len(sent_at):
                break
            time.sleep(0.1)
        for seq, shown_at in rows:
            if seq in sent_at:
                row_ms.append((shown_at / 1000 - offset - sent_at[seq]) * 1000)
    finally:
        if driver:
            driver.quit()
        messd.terminate()
        messd.wait(10)
        shutil.rmtree(work, ignore_errors=True)

    if len(row_ms) < len(push_ms):
        sys.exit("bench_web: only %d of %d points reached the page's list" % (len(row_ms), len(push_ms)))
    figures = []
    for p in (50, 99):
        push, row = percentile(push_ms, p), percentile(row_ms, p)
        figures.append({"id": "web.line_push.p%d" % p, "what": "ForcePt sent on 1066 -> its Hit line back on 1066 (the line protocol's push), p%d" % p,
                        "value": push, "unit": "ms", "reference_id": None, "reference": None, "ratio": None, "goal": None,
                        "met": None, "virtual_time": False})
        figures.append({"id": "web.browser_row.p%d" % p,
                        "what": "ForcePt sent on 1066 -> its row in the web panel's list in Chromium (same points), p%d" % p,
                        "value": row, "unit": "ms", "reference_id": "web.line_push.p%d" % p, "reference": push,
                        "ratio": row / push if push else None, "goal": None, "met": None, "virtual_time": False})
    out = {"bench": "web", "points": len(row_ms), "figures": figures,
           "distributions": [{"id": "web.line_push", "what": "the line protocol's push", "unit": "ms", "samples": push_ms},
                             {"id": "web.browser_row", "what": "the browser path", "unit": "ms", "samples": row_ms,
                              "reference_id": "web.line_push"}]}
    with open(args.json, "w") as f:
        json.dump(out, f, indent=1)
    for fig in figures:
        print("%-22s %8.2f ms  %s" % (fig["id"], fig["value"], fig["what"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
