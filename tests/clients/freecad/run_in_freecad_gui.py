# Runs a test script inside a real FreeCAD window: an Xvfb display of its own, a private HOME
# whose FreeCAD Mod folder links to clients/freecad (installed as the README says), and
# `freecad SCRIPT`; the script reads its arguments from IMESS_GUI_TEST (JSON), writes what it
# prints to a file (a GUI FreeCAD prints into its report view) and ends FreeCAD with its exit
# status. usage: run_in_freecad_gui.py SCRIPT BIN_DIR SOURCE_DIR [SCREENSHOT_DIR]
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time


def need(program, package):
    path = shutil.which(program)
    if not path:
        sys.exit("%s not found: install the Debian package %s (scripts/test installs it)" % (program, package))
    return path


def start_xvfb():
    """Xvfb on the first free display from :90; returns (process, ":N")."""
    xvfb = need("Xvfb", "xvfb")
    for n in range(90, 190):
        if os.path.exists("/tmp/.X11-unix/X%d" % n) or os.path.exists("/tmp/.X%d-lock" % n):
            continue
        proc = subprocess.Popen([xvfb, ":%d" % n, "-screen", "0", "1920x1080x24", "-dpi", "96", "-nolisten", "tcp"],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        end = time.time() + 10
        while time.time() < end and proc.poll() is None:
            if os.path.exists("/tmp/.X11-unix/X%d" % n):
                return proc, ":%d" % n
            time.sleep(0.05)
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    sys.exit("no free X display for Xvfb between :90 and :189")


def main():
    if len(sys.argv) < 4:
        sys.exit("usage: run_in_freecad_gui.py SCRIPT BIN_DIR SOURCE_DIR [SCREENSHOT_DIR]")
    script, bin_dir, source_dir = (os.path.abspath(a) for a in sys.argv[1:4])
    shots = os.path.abspath(sys.argv[4]) if len(sys.argv) > 4 else ""
    freecad = need("freecad", "freecad-python3")
    xvfb, display = start_xvfb()
    try:
        with tempfile.TemporaryDirectory(prefix="imess-freecad-gui-") as home:
            mod = os.path.join(home, ".local", "share", "FreeCAD", "Mod")
            os.makedirs(mod)
            os.symlink(os.path.join(source_dir, "clients", "freecad"), os.path.join(mod, "IMESS"))
            out = os.path.join(home, "output.txt")
            env = dict(os.environ, HOME=home, XDG_RUNTIME_DIR=home, DISPLAY=display, PYTHONDONTWRITEBYTECODE="1",
                       QTWEBENGINE_DISABLE_SANDBOX="1",  # FreeCAD's start page is a Chromium, which refuses root
                       IMESS_GUI_TEST=json.dumps({"bin": bin_dir, "source": source_dir, "output": out, "shots": shots}))
            env.pop("QT_QPA_PLATFORM", None)
            try:
                r = subprocess.run([freecad, script], env=env, timeout=150, stdout=subprocess.DEVNULL,
                                   stderr=subprocess.DEVNULL)
                code = r.returncode
            except subprocess.TimeoutExpired:
                code = None
            if os.path.exists(out):
                sys.stdout.write(open(out, encoding="utf-8", errors="replace").read())
            if code is None:
                print("FreeCAD did not finish within 150 s")
                return 1
            return code
    finally:
        xvfb.terminate()
        xvfb.wait(10)


if __name__ == "__main__":
    sys.exit(main())
