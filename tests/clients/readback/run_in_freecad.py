# Runs a Python script inside FreeCAD's headless interpreter (freecadcmd) with arguments, in a
# private HOME (no user configuration read or written); exit status = the script's.
"""usage: run_in_freecad.py SCRIPT [ARGS...]"""
import os
import re
import shutil
import subprocess
import sys
import tempfile


def freecadcmd():
    exe = shutil.which("freecadcmd") or shutil.which("FreeCADCmd")
    if not exe:
        sys.exit("freecadcmd not found: install the Debian package freecad-python3 "
                 "(scripts/test installs it)")
    return exe


# FreeCAD's console progress bars ("Recompute......", "(25 %)") and banner say nothing here.
NOISE = re.compile(r"\t*\(\s*\d+ %\)\t*|\x1b\[[0-9;]*m")
STEP_NAME = re.compile(r"^\s*[A-Za-z ]+\.{3,}\s*$")  # "Recompute......", "Loading points......"


def run(script, args, timeout=110):
    argv = [os.path.abspath(script)] + list(args)
    code = "import sys; sys.argv = %r; exec(compile(open(sys.argv[0]).read(), sys.argv[0], 'exec'))" % argv
    with tempfile.TemporaryDirectory(prefix="imess-freecad-home-") as home:
        env = dict(os.environ, HOME=home, XDG_RUNTIME_DIR=home, QT_QPA_PLATFORM="offscreen",
                   PYTHONDONTWRITEBYTECODE="1")  # no __pycache__ in the source tree
        try:
            r = subprocess.run([freecadcmd(), "-c", code], env=env, timeout=timeout, capture_output=True, text=True,
                               errors="replace")
        except subprocess.TimeoutExpired:
            print("freecadcmd did not finish within %d s" % timeout, file=sys.stderr)
            return 1
    for stream, out in ((r.stdout, sys.stdout), (r.stderr, sys.stderr)):
        for line in stream.splitlines():
            line = NOISE.sub("", line).rstrip()
            if line and not STEP_NAME.match(line):
                print(line, file=out)
    return r.returncode


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    sys.exit(run(sys.argv[1], sys.argv[2:]))
