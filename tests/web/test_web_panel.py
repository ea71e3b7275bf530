#!/usr/bin/env python3
"""The web panel in a real browser (Debian's chromium, chromedriver, python3-selenium) against
a real messd: the page loads and shows the position, Load/Run of a shipped program shows its
progress to ProgEnd, press-and-hold -Z touches the cube and the hit appears in the list and the
views, 40 ForcePt points reach the page's list (the delay after the line protocol's push is
printed as figures), a reloaded page lists the journal's newest hits, a scan's points are the 3-D
view's cloud and its summary line, drawn at most five times a second, releasing a jog button stops, closing the tab mid-jog stops the machine, and a browser
from a host that may not control watches but cannot move. Screenshots of each state go to
OUT_DIR (docs/web/ holds one set). Usage: test_web_panel.py BIN_DIR SOURCE_DIR OUT_DIR"""
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time

try:
    from selenium import webdriver
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    from selenium.webdriver.chrome.service import Service
except ImportError:
    sys.exit("test_web_panel: python3-selenium is missing (apt-get install python3-selenium chromium chromium-driver)")

BIN, SRC, OUT = sys.argv[1:4]
os.makedirs(OUT, exist_ok=True)
failures = []


STARTED = time.monotonic()


def check(ok, what):
    print("%s %5.1f s  %s" % ("ok  " if ok else "FAIL", time.monotonic() - STARTED, what), flush=True)
    if not ok:
        failures.append(what)
    return ok


class Messd:
    """build/bin/messd on free loopback ports, with its own journal."""

    def __init__(self, extra=()):
        self.dir = tempfile.mkdtemp(prefix="imess-web-test-")
        args = [os.path.join(BIN, "messd"), "--port", "0", "--listen", "127.0.0.1", "--no-rt",
                "--journal", os.path.join(self.dir, "journal"), "--frames", os.path.join(self.dir, "frames.json"),
                "--programs", os.path.join(SRC, "examples", "programs")] + list(extra)
        self.proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        lines = [self.proc.stdout.readline() for _ in range(3)]
        self.port = int(re.search(r":(\d+)$", lines[0].strip()).group(1))
        web = re.search(r"web panel on (http://[\d.]+:\d+/)", lines[2])
        if not web:
            raise SystemExit("messd printed no web panel line: %r" % lines)
        self.url = web.group(1)

    def stop(self):
        self.proc.terminate()
        self.proc.wait(10)
        shutil.rmtree(self.dir, ignore_errors=True)


class Line:
    """A telnet-like client on 1066 that watches what every client sees; a thread reads it and
    stamps each line with its arrival (time.monotonic())."""

    def __init__(self, port):
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=5)
        self.sock.settimeout(None)
        self.lines = []  # (arrival, text)
        self.cursor = 0
        self.cond = threading.Condition()
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        buf = b""
        while True:
            try:
                data = self.sock.recv(65536)
            except OSError:
                data = b""
            now = time.monotonic()
            with self.cond:
                if not data:
                    self.lines.append((now, None))
                    self.cond.notify_all()
                    return
                buf += data
                while b"\n" in buf:
                    line, buf = buf.split(b"\n", 1)
                    self.lines.append((now, line.decode(errors="replace")))
                self.cond.notify_all()

    def until(self, prefix, timeout):
        deadline = time.time() + timeout
        with self.cond:
            while True:
                while self.cursor < len(self.lines):
                    _, text = self.lines[self.cursor]
                    self.cursor += 1
                    if text is None:
                        return None
                    if text.startswith(prefix):
                        return text
                left = deadline - time.time()
                if left <= 0:
                    return None
                self.cond.wait(left)

    def skip(self):
        """Reads on from the newest line: until() finds only what comes after."""
        with self.cond:
            self.cursor = len(self.lines)

    def find(self, prefix):
        """The first line with prefix seen so far, read or not: (arrival, text)."""
        with self.cond:
            for at, text in self.lines:
                if text and text.startswith(prefix):
                    return at, text
        return None

    def request(self, line):
        self.sock.sendall((line + "\n").encode())
        verb = line.split()[0]
        return self.until("Ok " + verb, 5) or self.until("Err", 1)


def percentile(values, p):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(p / 100.0 * (len(ordered) - 1))))]


DOWNLOADS = tempfile.mkdtemp(prefix="imess-web-downloads-")


def browser():
    # --in-process-gpu: the software GL (SwiftShader) the 3-D view draws with runs in the page's
    # process; in a GPU process of its own, on a loaded 2-core host, the page's main thread was
    # seen to wait on it for more than the dead-man's 1.5 s (Watch then aborted the program).
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    options.add_experimental_option("prefs", {"download.default_directory": DOWNLOADS, "download.prompt_for_download": False})
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--in-process-gpu", "--window-size=1024,768",
              "--disable-dev-shm-usage", "--user-data-dir=" + tempfile.mkdtemp(prefix="imess-chromium-")):
        options.add_argument(a)
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)


def wait_for(fn, timeout, step=0.05):
    deadline = time.time() + timeout
    while time.time() < deadline:
        try:
            value = fn()
            if value:
                return value
        except Exception:  # the element not there yet
            pass
        time.sleep(step)
    return None


def text(driver, element_id):
    return driver.find_element(By.ID, element_id).text


def shot(driver, name):
    driver.save_screenshot(os.path.join(OUT, name + ".png"))


def position(driver):
    return " ".join(text(driver, "pos-" + a) for a in "XYZ")


def file_text(path):
    with open(path) as f:
        return f.read()


def without_time(dmis):  # DMIS names the time it was written: ", 2026-11-29T03:40:00" on its second line
    return re.sub(r"(measured points[^\n]*), [0-9T:-]+\n", r"\1\n", dmis, count=1)


def check_files_and_fit(driver, captures, captured):
    """The page's downloads of the program's eight touches are the files messcap captured of
    them, and its circle fit is what messcap fit prints for messcap's .hits file."""
    for c in captures:
        c.wait(10)
    for ext in ("csv", "xyz", "dmi", "hits"):
        driver.find_element(By.ID, "download-" + ext).click()
        got = wait_for(lambda: os.path.exists(os.path.join(DOWNLOADS, "points." + ext)) and
                       file_text(os.path.join(DOWNLOADS, "points." + ext)), 5)
        want = file_text(os.path.join(captured, "points." + ext))
        if ext == "dmi":
            got, want = without_time(got or ""), without_time(want)
        check(got == want, "the page's %s download is messcap's capture of the same hits (%d bytes)" % (ext, len(want)))
    driver.find_element(By.CSS_SELECTOR, "#fit-kind option[value='circle']").click()
    driver.find_element(By.ID, "fit").click()
    line = wait_for(lambda: text(driver, "fit-line"), 5)
    fitted = subprocess.run([os.path.join(BIN, "messcap"), "fit", "circle", os.path.join(captured, "points.hits")],
                            capture_output=True, text=True).stdout.strip()
    page, messcap = json.loads(line or "{}"), json.loads(fitted)
    flat = lambda v: v if isinstance(v, list) else [v]
    close = lambda a, b: a == b if isinstance(a, str) or isinstance(b, str) else abs(a - b) < 1e-9
    same = page.keys() == messcap.keys() and all(
        len(flat(page[k])) == len(flat(messcap[k])) and all(close(a, b) for a, b in zip(flat(page[k]), flat(messcap[k])))
        for k in page)
    check(same, "the page's circle fit is messcap fit's of the same hits:\n  page    %s\n  messcap %s" % (line, fitted))
    check("Ø 30.0000" in text(driver, "fit-result"), "the fit shows the bore's diameter: " + text(driver, "fit-result"))
    check(wait_for(lambda: "fit" in driver.find_element(By.ID, "view3d").get_attribute("data-extras"), 5),
          "the fitted circle is drawn in the 3-D view")
    shot(driver, "panel-fit")


def check_inspection(driver):
    """A plan of the programs folder (examples/programs/cube-top.plan.json) measured by messcap
    inspect, which messd's web front end starts: its table and the HTML report it wrote."""
    check(wait_for(lambda: "cube-top.plan.json" in text(driver, "plan-list"), 5), "the inspection plans are listed")
    driver.find_element(By.CSS_SELECTOR, "#plan-list option[value='cube-top.plan.json']").click()
    driver.find_element(By.ID, "inspect-run").click()
    done = wait_for(lambda: driver.find_element(By.ID, "inspect-status").get_attribute("data-status") is not None
                    and text(driver, "inspect-status"), 40)
    check(done and "every characteristic in tolerance" in done, "messcap inspect measured the plan: %s" % done)
    check(re.search(r"top flatness\s+flatness\s+0\.0000\s+0\.0000.*ok", text(driver, "inspect-table")) is not None,
          "its table is shown: %r" % text(driver, "inspect-table")[-200:])
    frame = driver.find_element(By.ID, "inspect-report")
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", frame)
    driver.switch_to.frame(frame)
    report = wait_for(lambda: driver.find_element(By.TAG_NAME, "body").text, 5) or ""
    driver.switch_to.default_content()
    check("top flatness" in report and "cube-1996-top" in report, "messcap's HTML report is shown: %r" % report[:120])
    shot(driver, "panel-inspection")


def scanning_config():
    """tests/e2e/fast-cmm.json (the default CMM, brisk, in loop time at speed 4) with the measuring
    probe of config/sim-servo-card-scanning.json: the scanning machine, as fast as the rest. On the
    card's request-reply link, whose deflection comes every 1 ms cycle (the streamed line's status
    frames come every few ms), so a scan brings well over a thousand points a second."""
    with open(os.path.join(SRC, "tests", "e2e", "fast-cmm.json")) as f:
        config = json.load(f)
    with open(os.path.join(SRC, "config", "sim-servo-card-scanning.json")) as f:
        config["sim"]["probe"] = json.load(f)["sim"]["probe"]
    config["backend"] = {"type": "sim-servo-card", "link": "request-reply"}
    path = os.path.join(tempfile.mkdtemp(prefix="imess-web-config-"), "scanning.json")
    with open(path, "w") as f:
        json.dump(config, f)
    return path


def check_scan(driver, watcher):
    """A scan of the bore, a full turn at 20 mm/s with a point every 0.05 mm (400 a second of the
    machine's time, some 1 600 a second of wall time at sim speed 4 when the host keeps up): the page's
    cloud holds exactly the Scan lines messd sent, its line in the points panel says how many, the
    view drew at most five times a second meanwhile, and framing everything shows the cloud."""
    view = lambda key: driver.find_element(By.ID, "view3d").get_attribute("data-" + key)
    send = lambda line: driver.execute_script("return window.imess.line(arguments[0]).then((r) => r.line)", line)
    for line in ("GoTo 460 350 100", "GoTo 460 350 60"):
        watcher.skip()
        check(send(line) == "Ok GoTo" and watcher.until("State idle", 10) is not None, "the page moves the probe: " + line)
    check(send("Set ScanStep 0.05") == "Ok Set", "a point every 0.05 mm")
    watcher.skip()
    page_now = lambda: driver.execute_script("return performance.now()")  # noqa: E731
    since, started = page_now(), time.monotonic()
    reply = send("ScanCirc 77 460 350 60 475 350 60 0 0 1 360 bore 20")
    check(reply == "Ok ScanCirc", "the page queues a full turn of the bore: %s" % reply)
    end = watcher.until(("Done 77", "Failed 77"), 30)
    elapsed = time.monotonic() - started
    check(end == "Done 77", "the scan ends: %s" % end)
    with watcher.cond:
        arrived = [(at, t) for at, t in watcher.lines if t and t.startswith("Scan ") and t.split()[2] == "77"]
    scanned = [t for _, t in arrived]
    n = len(scanned)
    check(wait_for(lambda: view("scan-points") == str(n), 5),
          "the page's cloud holds exactly the %d Scan lines messd sent (%s)" % (n, view("scan-points")))
    until = page_now()
    times = [t for t in driver.execute_script("return window.imessView3d.drawTimes()") if since <= t <= until]
    gaps = [b - a for a, b in zip(times, times[1:])]
    span = arrived[-1][0] - arrived[0][0] if n > 1 else 0
    print("figures: %d scan points in %.2f s on 1066 (%.0f a second), %d drawings of the 3-D view in the %.2f s "
          "from ScanCirc to all points in the page, at least %.0f ms apart" % (
              n, span, (n - 1) / span if span else 0, len(times), (until - since) / 1000, min(gaps or [0])), flush=True)
    check(n > 500 and len(times) >= 2 and min(gaps) >= 200,
          "at most five drawings a second while the points come: %d, none closer than 200 ms to the one before"
          % len(times))
    line = wait_for(lambda: driver.find_element(By.CSS_SELECTOR, "#scans li[data-id='77']"), 5)
    summary = wait_for(lambda: line.get_attribute("data-points") == str(n) and "done" in line.text and line.text, 5)
    first, last = scanned[0].split()[1], scanned[-1].split()[1]
    check(summary == "scan 77: %d points (%s–%s) done" % (n, first, last), "the points panel says so in one line: %r" % summary)
    check(len(driver.find_elements(By.CSS_SELECTOR, "#scans li")) == 1 and
          len(driver.find_elements(By.CSS_SELECTOR, "#points tbody tr")) == 20, "one line for the scan, no row per point")
    fit = driver.find_element(By.ID, "view-fit")
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", fit)
    fit.click()
    far = [float(v) for v in scanned[n // 2].split()[3:6]]  # across the bore from the start
    rgb = driver.execute_script("return window.imessView3d.pixelAt(...arguments)", *far)
    check(rgb and rgb[0] > 120 and rgb[0] > 2 * rgb[1] and rgb[2] > rgb[1],
          "framed, the cloud is drawn in the scans' magenta where its point %s is: rgb %s" % (far, rgb))
    shot(driver, "panel-scan")
    watcher.skip()
    check(send("Set ScanStep 0.1") == "Ok Set" and send("GoTo 460 350 100") == "Ok GoTo" and
          watcher.until("State idle", 10) is not None, "out of the bore again")


def main():
    messd = Messd(["--config", scanning_config()])
    watcher = Line(messd.port)
    driver = browser()
    try:
        driver.get(messd.url)
        check(wait_for(lambda: position(driver) == "430.000 330.000 100.000", 10), "the page shows the position 430.000 330.000 100.000")
        check(wait_for(lambda: text(driver, "link") == "online", 5), "the page is connected")
        status = watcher.request("Status")
        state = re.search(r" State (\w+) ", status).group(1)
        check(wait_for(lambda: text(driver, "state") == state, 5), "the page shows the state Status says (%s)" % state)
        check(wait_for(lambda: text(driver, "control") == "none", 5), "the page shows nobody in control")
        # Stats: the motion loop's wake-up latency, as Stats says it.
        stats = driver.find_element(By.ID, "stats-refresh")
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", stats)
        stats.click()
        shown = wait_for(lambda: re.search(r"LatP99 \d+", text(driver, "stats")) and text(driver, "stats"), 5)
        check(shown and "Cycles" in shown and "Overruns" in shown, "Stats shows the loop's latency: %r" % (shown or "")[:80])
        driver.execute_script("window.scrollTo(0, 0)")
        shot(driver, "panel-connected")

        # A shipped program: Load shows the check's summary, Run its blocks up to ProgEnd.
        check(wait_for(lambda: "bore-inspection.ngc" in text(driver, "program-list"), 5), "the programs folder is listed")
        driver.find_element(By.CSS_SELECTOR, "#program-list option[value='bore-inspection.ngc']").click()
        driver.find_element(By.ID, "program-load").click()
        check(wait_for(lambda: text(driver, "program-check").startswith("Ok Load bore-inspection.ngc"), 10),
              "Load shows the check's summary: " + text(driver, "program-check"))
        # Its path in the 3-D view: the segments the check planned, as many as Load counts.
        segments = re.search(r" Segments (\d+)", text(driver, "program-check"))
        view = lambda key: driver.find_element(By.ID, "view3d").get_attribute("data-" + key)
        check(segments and wait_for(lambda: view("path-segments") == segments.group(1), 5) and "program" in view("extras"),
              "the program's path is drawn: %s segments, as Load says (%s)" % (view("path-segments"), segments and segments.group(1)))
        # messcap captures the same touches on 1066, into the files the page's downloads must equal.
        captured = tempfile.mkdtemp(prefix="imess-web-messcap-")
        captures = [subprocess.Popen([os.path.join(BIN, "messcap"), "127.0.0.1:%d" % messd.port, "-n", "8", "-o",
                                      os.path.join(captured, "points." + ext)], stdout=subprocess.DEVNULL,
                                     stderr=subprocess.PIPE, text=True) for ext in ("csv", "xyz", "dmi", "hits")]
        for c in captures:
            check("connected" in c.stderr.readline(), "messcap is capturing beside the page")
        driver.find_element(By.ID, "program-run").click()
        check(wait_for(lambda: "block" in text(driver, "program-block"), 10), "Run shows the current block")
        block_line = lambda: re.search(r" line (\d+) block", text(driver, "program-block") + " line - block").group(1)
        check(wait_for(lambda: view("path-line") == block_line(), 10),
              "the current block's line is highlighted in the path (line %s, the Block's %s)" % (view("path-line"), block_line()))
        shot(driver, "panel-program-running")
        end = wait_for(lambda: "ProgEnd" in text(driver, "program-block") and text(driver, "program-block"), 120)
        check(end and "ProgEnd bore-inspection.ngc ok" in end, "the program runs to ProgEnd ok: %s" % end)
        progress = driver.find_element(By.ID, "program-progress")
        check(progress.get_attribute("value") == progress.get_attribute("max"), "the progress bar is full at ProgEnd")
        hits_of_program = len(driver.find_elements(By.CSS_SELECTOR, "#points tbody tr"))
        check(hits_of_program == 8, "the program's 8 touches are in the points list (%d)" % hits_of_program)
        shot(driver, "panel-program-ended")
        check_files_and_fit(driver, captures, captured)
        check_inspection(driver)
        clear = driver.find_element(By.ID, "clear-points")
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", clear)
        clear.click()
        watcher.request("Release")  # nobody holds control now; the page's jog takes it
        driver.find_element(By.ID, "console-line").send_keys("GoTo 430 330 100\n")
        check(wait_for(lambda: position(driver) == "430.000 330.000 100.000", 20), "back above the cube")

        # Press and hold -Z: the probe touches the top face, the hit is in the list and the views.
        minus_z = driver.find_element(By.ID, "jog-Z-")
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", minus_z)
        ActionChains(driver).click_and_hold(minus_z).perform()
        row = wait_for(lambda: driver.find_elements(By.CSS_SELECTOR, "#points tbody tr"), 15)
        ActionChains(driver).release().perform()
        cells = [c.text for c in row[0].find_elements(By.TAG_NAME, "td")] if row else []
        check(cells[1:4] == ["430.000", "330.000", "80.000"], "holding -Z touches the top: the hit in the list %s" % cells)
        # The 3-D view (three.js from Debian's libjs-three, served by messd as /three/): the
        # scene holds the hit as its newest point, and the newest point's colour is drawn
        # where that point appears on the canvas.
        view = lambda key: driver.find_element(By.ID, "view3d").get_attribute("data-" + key)
        check(wait_for(lambda: view("last") == "430.000 330.000 80.000" and view("points") == "1", 5),
              "the hit is the 3-D view's one point: %s (%s points)" % (view("last"), view("points")))
        check(wait_for(lambda: view("probe") == position(driver), 5), "the probe is in the 3-D view where the page says it is (%s)" % view("probe"))
        rgb = driver.execute_script("return window.imessView3d.pixelAt(430, 330, 80)")
        # (red seen through the see-through probe ball, which stands just above the point)
        check(rgb and rgb[0] > 90 and rgb[0] > 2 * rgb[1] and rgb[0] > 2 * rgb[2],
              "the hit is drawn red (the newest) in the 3-D view: rgb %s" % rgb)
        shot(driver, "panel-hit")

        # The browser path against the line protocol's push, in the same run: for each
        # ForcePt's Hit, its line's arrival on 1066 here and its row's appearance in the page's
        # list (the page stamps it with its wall clock, brought to time.monotonic() here).
        offset = time.time() - time.monotonic()
        first = len(driver.find_elements(By.CSS_SELECTOR, "#points tbody tr"))
        for _ in range(40):
            driver.execute_script("window.imess.send('ForcePt')")
            time.sleep(0.05)
        wait_for(lambda: len(driver.find_elements(By.CSS_SELECTOR, "#points tbody tr")) >= first + 40, 10)
        rows = driver.execute_script(
            "return [...document.querySelectorAll('#points tbody tr')].map(r => [Number(r.dataset.seq), Number(r.dataset.shownAt)]);")
        later_ms = []
        for seq, shown_at in rows[: len(rows) - first]:
            found = watcher.find("Hit %d " % seq)
            if found:
                later_ms.append((shown_at / 1000 - offset - found[0]) * 1000)
        if check(len(later_ms) >= 30, "the browser path measured for %d points" % len(later_ms)):
            print("figures: a hit's row in the page after its line on 1066: p50 %.2f ms p99 %.2f ms (%d points)"
                  % (percentile(later_ms, 50), percentile(later_ms, 99), len(later_ms)), flush=True)
            check(percentile(later_ms, 50) < 250, "a point reaches the page's list within 250 ms of the line protocol's push (p50)")

        # A reloaded page starts with the journal's newest 20 hits (Replay), the newest on top.
        newest = max(seq for seq, _ in rows)
        driver.refresh()
        listed = wait_for(lambda: len(driver.find_elements(By.CSS_SELECTOR, "#points tbody tr")) == 20 and driver.execute_script(
            "return [...document.querySelectorAll('#points tbody tr')].map(r => Number(r.dataset.seq));"), 10)
        check(listed == list(range(newest, newest - 20, -1)), "a reloaded page lists the journal's newest 20 hits: %s" % listed)
        wait_for(lambda: position(driver) != "– – –" and text(driver, "link") == "online", 5)
        check_scan(driver, watcher)

        # Releasing a held button stops the machine.
        wait_for(lambda: text(driver, "state") == "idle", 5)
        hold = ActionChains(driver)
        hold.click_and_hold(driver.find_element(By.ID, "jog-X+")).perform()
        check(watcher.until("State jog", 5) is not None, "holding X+ jogs")
        time.sleep(0.4)
        shot(driver, "panel-jogging")
        released = time.time()
        ActionChains(driver).release().perform()
        stopping = watcher.until("State idle", 5)
        check(stopping is not None and time.time() - released < 2.0,
              "releasing the button stops the machine (idle %.2f s after)" % (time.time() - released))

        # Closing the tab mid-jog stops the machine (the WebSocket closes: control is lost).
        ActionChains(driver).click_and_hold(driver.find_element(By.ID, "jog-Y+")).perform()
        check(watcher.until("State jog", 5) is not None, "holding Y+ jogs")
        closed = time.time()
        driver.quit()
        driver = None
        stopped = watcher.until("State stopping", 3)
        check(stopped is not None and time.time() - closed < 1.5,
              "closing the tab mid-jog stops the machine within the dead-man time (%.2f s)" % (time.time() - closed))
    finally:
        if driver:
            driver.quit()
        messd.stop()

    # A browser on a host that may not control: it watches, its jog is refused, nothing moves.
    config = os.path.join(tempfile.mkdtemp(prefix="imess-web-config-"), "observe.json")
    with open(config, "w") as f:
        f.write('{ "motion": { "max_speed": 100, "max_accel": 4000, "max_velocity": 400 }, "sim": { "time": "loop" },'
                ' "control": { "hosts": ["10.0.0.0/8"], "observe_hosts": ["0.0.0.0/0"] } }')
    messd = Messd(["--config", config])
    driver = browser()
    try:
        driver.get(messd.url)
        check(wait_for(lambda: position(driver) == "430.000 330.000 100.000", 10), "an observer's page shows the position")
        ActionChains(driver).click_and_hold(driver.find_element(By.ID, "jog-Z-")).perform()
        refused = wait_for(lambda: "Err 210" in text(driver, "log") and text(driver, "log"), 5)
        ActionChains(driver).release().perform()
        check(refused and "may observe but not control" in refused, "an observer's jog is refused with Err 210")
        time.sleep(0.5)
        check(position(driver) == "430.000 330.000 100.000", "nothing moved")
        shot(driver, "panel-observer")
    finally:
        messd.stop()

    # A machine whose axes are not X Y Z (the MRM arm: X Y C U V), in the same browser: a pair
    # of jog buttons for each of its axes, none for Z, and holding C+ turns C (JogAx).
    messd = Messd(["--config", os.path.join(SRC, "config", "sim-mrm-arm.json")])
    arm = Line(messd.port)
    try:
        driver.get(messd.url)
        check(wait_for(lambda: driver.find_element(By.ID, "jog-C+").is_displayed() and
                       not driver.find_element(By.ID, "jog-Z-").is_displayed(), 10),
              "the arm's page has jog buttons for C U V and none for Z: %s" % [
                  b.text for b in driver.find_elements(By.CSS_SELECTOR, ".jog-button") if b.is_displayed()])
        c_of = lambda: float(text(driver, "pos-Cx"))
        before = c_of()
        turn = driver.find_element(By.ID, "jog-C+")
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", turn)
        ActionChains(driver).click_and_hold(turn).perform()
        check(arm.until("State jog", 5) is not None, "holding C+ jogs the arm")
        turned = wait_for(lambda: c_of() > before + 1 and c_of(), 5)
        shot(driver, "panel-arm")
        ActionChains(driver).release().perform()
        check(arm.until("State idle", 5) is not None, "releasing C+ stops it")
        check(turned is not None, "C turned from %.3f to %s" % (before, turned))
    finally:
        driver.quit()
        messd.stop()

    if failures:
        print("test_web_panel: %d failed" % len(failures))
        return 1
    print("test_web_panel: all passed; screenshots in " + OUT)
    return 0


if __name__ == "__main__":
    sys.exit(main())
