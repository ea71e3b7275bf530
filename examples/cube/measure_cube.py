#!/usr/bin/env python3
"""Measures the 1996 worked-example cube fully automatically with messd's Probe cycle.

The part (the default simulated machine's scene, config/sim-servo-card.json): a block on the
table with a vertical through-bore and a rounded edge between its front face and its top.
The script probes the table (3 points), the four sides (3 points each), the top (3 points),
the bore (6 points at half height) and the fillet (1 point along its 45-degree normal); it
fits planes and the bore circle with `messcap fit` and constructs length, width, height,
bore diameter, the part's turn about the vertical and the fillet radius (the circle tangent
to the front and top planes through the fillet point).

Usage: measure_cube.py [HOST[:PORT]] [--feed MM_S] [--messcap PATH] [--json]
Needs only Python 3's standard library and messcap (on PATH, or --messcap).
Exit status: 0 measured, 1 messd unreachable / a probe failed / a fit failed, 2 bad arguments.
"""
import argparse
import json
import math
import shutil
import socket
import subprocess
import sys

# The nominal part, in machine coordinates (mm). Probe targets are ball-centre positions:
# the nominal surface point plus the tip radius along the outward normal.
CENTRE = (460.0, 350.0, 40.0)
SIZE = (120.0, 100.0, 80.0)
BORE_DIAMETER = 30.0
FILLET_RADIUS = 10.0
SAFE_Z = 120.0      # clear of the part
CLEARANCE = 6.0     # start of each probing move, mm off the nominal surface
SEARCH = 1.5        # SearchDist: how far past the nominal point a probe still looks
TIP_RADIUS = 2.0


class ProbeFailed(RuntimeError):
    pass


class Messd:
    """One connection: a command gets exactly one reply; events are kept as they come."""

    def __init__(self, host, port):
        self.sock = socket.create_connection((host, port), timeout=30)
        self.buf = b""
        self.hits = {}      # command id -> [(surface point, approach direction)]
        self.ended = {}     # command id -> "Done" or the Failed line
        self.fault = None   # the last Fault event

    def _line(self):
        while b"\n" not in self.buf:
            data = self.sock.recv(4096)
            if not data:
                raise ConnectionError("messd closed the connection")
            self.buf += data
        line, self.buf = self.buf.split(b"\n", 1)
        return line.decode().rstrip("\r")

    def _event(self, line):
        words = line.split()
        if words[0] == "Hit" and len(words) >= 11:
            cmd = int(words[2])
            point = tuple(float(w) for w in words[3:6])
            direction = tuple(float(w) for w in words[6:9])
            self.hits.setdefault(cmd, []).append((point, direction))
        elif words[0] == "Done":
            self.ended[int(words[1])] = "Done"
        elif words[0] == "Failed":
            self.ended[int(words[1])] = line
        elif words[0] == "Fault":
            self.fault = line

    def command(self, text):
        self.sock.sendall((text + "\n").encode())
        while True:
            line = self._line()
            if line.startswith("Ok ") or line.startswith("Err "):
                if line.startswith("Err "):
                    raise ProbeFailed(f"messd refused '{text}': {line}")
                return line
            self._event(line)

    def wait_end(self, cmd):
        while cmd not in self.ended:
            self._event(self._line())
        if self.ended[cmd] != "Done":
            failed = self.ended[cmd]
            if " Faulted" in failed:  # which fault: its event follows the Failed line
                self.sock.settimeout(2)
                try:
                    while self.fault is None:
                        self._event(self._line())
                except OSError:
                    pass
                failed += f" ({self.fault})" if self.fault else ""
            raise ProbeFailed(failed)


class Operator:
    def __init__(self, messd, feed):
        self.m = messd
        self.feed = feed
        self.next_id = 1

    def _queued(self, verb, xyz, feed):
        cmd = self.next_id
        self.next_id += 1
        x, y, z = xyz
        self.m.command(f"{verb} {cmd} X{x:.4f} Y{y:.4f} Z{z:.4f} F{feed:.1f}")
        self.m.wait_end(cmd)
        return cmd

    def move(self, xyz):
        self._queued("MoveTo", xyz, self.feed)

    def probe(self, surface, outward):
        """Probes the nominal surface point along -outward; returns the measured surface point."""
        start = add(surface, scale(outward, CLEARANCE + TIP_RADIUS))
        target = add(surface, scale(outward, TIP_RADIUS))
        self.move(start)
        cmd = self._queued("Probe", target, self.feed)
        hits = self.m.hits.get(cmd, [])
        if len(hits) != 1:
            raise ProbeFailed(f"Probe {cmd} at {fmt(target)} ended with {len(hits)} hits")
        self.move(start)
        return hits[0][0]


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def scale(a, s):
    return tuple(x * s for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def fmt(p):
    return " ".join(f"{v:.4f}" for v in p)


def fit(messcap, kind, points):
    text = "".join(f"{p[0]:.6f} {p[1]:.6f} {p[2]:.6f}\n" for p in points)
    run = subprocess.run([messcap, "fit", kind, "-"], input=text, capture_output=True, text=True)
    if run.returncode != 0:
        raise ProbeFailed(f"messcap fit {kind}: {run.stderr.strip()}")
    return json.loads(run.stdout)


def oriented_plane(messcap, points, outward):
    """A fitted plane (point, unit normal) whose normal points out of the material."""
    plane = fit(messcap, "plane", points)
    normal = tuple(plane["normal"])
    if dot(normal, outward) < 0:
        normal = scale(normal, -1)
    return tuple(plane["point"]), normal


def height_over(plane, p):
    return dot(sub(p, plane[0]), plane[1])


def measure(op, messcap):
    cx, cy, cz = CENTRE
    lx, ly, lz = (s / 2 for s in SIZE)
    top_z = cz + lz
    up, down = (0, 0, 1), (0, 0, -1)

    def face(points, outward):
        """Probes points on one face: sides from 20 mm off the face, reached over the top;
        upward faces each from straight above."""
        got = []
        side = outward[2] == 0
        if side:
            off = add(points[0], scale(outward, 20))
            op.move((off[0], off[1], SAFE_Z))
        for p in points:
            if not side:
                op.move((p[0], p[1], SAFE_Z))
            got.append(op.probe(p, outward))
            if not side:
                op.move((p[0], p[1], SAFE_Z))
        if side:
            off = add(points[-1], scale(outward, 20))
            op.move((off[0], off[1], SAFE_Z))
        return got

    # Every side is reached over the top: lift, move over, go down beside the part.
    op.move((cx, cy, SAFE_Z))
    table = face([(cx - 160, cy - 150, 0), (cx + 240, cy - 130, 0), (cx - 140, cy + 170, 0)], up)
    left = face([(cx - lx, cy - 30, 20), (cx - lx, cy + 35, 25), (cx - lx, cy, 60)], (-1, 0, 0))
    right = face([(cx + lx, cy - 30, 20), (cx + lx, cy + 35, 25), (cx + lx, cy, 60)], (1, 0, 0))
    front = face([(cx - 40, cy - ly, 20), (cx + 40, cy - ly, 20), (cx, cy - ly, 50)], (0, -1, 0))
    back = face([(cx - 40, cy + ly, 20), (cx + 40, cy + ly, 20), (cx, cy + ly, 50)], (0, 1, 0))
    top = face([(cx - 40, cy - 20, top_z), (cx + 40, cy + 30, top_z), (cx - 40, cy + 35, top_z)], up)

    # The bore: from its middle at half height, six points on the wall.
    op.move((cx, cy, SAFE_Z))
    op.move((cx, cy, cz))
    bore = []
    for k in range(6):
        a = math.radians(15 + 60 * k)
        inward = (-math.cos(a), -math.sin(a), 0)  # the wall's outward normal points to the axis
        wall = (cx + BORE_DIAMETER / 2 * math.cos(a), cy + BORE_DIAMETER / 2 * math.sin(a), cz)
        bore.append(op.probe(wall, inward))
        op.move((cx, cy, cz))
    op.move((cx, cy, SAFE_Z))

    # The fillet along its normal, halfway round the edge.
    n = (0, -math.sqrt(0.5), math.sqrt(0.5))
    edge_centre = (cx, cy - ly + FILLET_RADIUS, top_z - FILLET_RADIUS)
    fillet_point = op.probe(add(edge_centre, scale(n, FILLET_RADIUS)), n)
    op.move((cx, cy - ly - 20, SAFE_Z))

    return construct(messcap, table, left, right, front, back, top, bore, fillet_point)


def construct(messcap, table, left, right, front, back, top, bore, fillet_point):
    table_pl = oriented_plane(messcap, table, (0, 0, 1))
    left_pl = oriented_plane(messcap, left, (-1, 0, 0))
    right_pl = oriented_plane(messcap, right, (1, 0, 0))
    front_pl = oriented_plane(messcap, front, (0, -1, 0))
    back_pl = oriented_plane(messcap, back, (0, 1, 0))
    top_pl = oriented_plane(messcap, top, (0, 0, 1))
    circle = fit(messcap, "circle", bore)

    # Distances between opposite faces: each face's points measured against the other's plane.
    def between(plane, points):
        return sum(-height_over(plane, p) for p in points) / len(points)

    length = (between(left_pl, right) + between(right_pl, left)) / 2
    width = (between(front_pl, back) + between(back_pl, front)) / 2
    height = between(top_pl, table)
    turn = math.degrees(math.atan2(-left_pl[1][1], -left_pl[1][0]))
    # Fillet: the circle tangent to the front and top planes through the measured point. a, b:
    # how far inside each plane the point lies; centre at depth R below both: (R-a)^2 + (R-b)^2 = R^2.
    a = -height_over(front_pl, fillet_point)
    b = -height_over(top_pl, fillet_point)
    fillet_r = a + b + math.sqrt(2 * a * b)
    return {
        "length": length, "width": width, "height": height,
        "bore_diameter": circle["diameter"], "bore_centre": circle["center"],
        "bore_axis_tilt_deg": math.degrees(math.acos(min(1.0, abs(dot(circle["normal"], table_pl[1]))))),
        "turn_deg": turn, "fillet_radius": fillet_r,
        "points": len(table) + len(left) + len(right) + len(front) + len(back) + len(top) + len(bore) + 1,
    }


# The printed report: each figure with its unit, lengths to 0.1 um and angles to 0.0001 degree
# (the simulated part is exact to far below that; a real one shows its deviations there).
REPORT = (
    ("length", "length", "mm"),
    ("width", "width", "mm"),
    ("height", "height", "mm"),
    ("bore diameter", "bore_diameter", "mm"),
    ("bore centre", "bore_centre", "mm"),
    ("bore axis tilt", "bore_axis_tilt_deg", "deg"),
    ("turn about z", "turn_deg", "deg"),
    ("fillet radius", "fillet_radius", "mm"),
)


def report(result):
    """'length            120.0000 mm' ..., then the number of points."""
    lines = []
    for label, key, unit in REPORT:
        value = result[key]
        values = value if isinstance(value, (list, tuple)) else [value]
        text = " ".join(f"{v:.4f}" for v in values)
        lines.append(f"{label:16} {text:>9} {unit}")
    lines.append(f"{'points':16} {result['points']:>9}")
    return "\n".join(lines)


def parse_args(argv):
    ap = argparse.ArgumentParser(description="Measure the worked-example cube with messd's Probe cycle.")
    ap.add_argument("address", nargs="?", default="localhost:1066", help="HOST[:PORT] of messd (localhost:1066)")
    ap.add_argument("--feed", type=float, default=100.0, help="positioning speed, mm/s (100)")
    ap.add_argument("--messcap", default=shutil.which("messcap") or "messcap", help="the messcap program")
    ap.add_argument("--json", action="store_true", help="print the result as one JSON object")
    args = ap.parse_args(argv)
    host, _, port = args.address.rpartition(":") if ":" in args.address else (args.address, "", "1066")
    host = host or "localhost"
    try:
        args.port = int(port)
    except ValueError:
        ap.error(f"PORT must be a number, got '{port}'")
    args.host = host
    if not args.feed > 0:
        ap.error(f"--feed must be above 0 mm/s, got {args.feed}")
    return args


def main(argv):
    args = parse_args(argv)
    try:
        messd = Messd(args.host, args.port)
    except OSError as e:
        print(f"measure_cube: no messd on {args.host}:{args.port} ({e})", file=sys.stderr)
        return 1
    try:
        messd.command("Hello measure_cube")
        messd.command("Take")
        messd.command(f"Set TipRadius {TIP_RADIUS}")
        messd.command(f"Set SearchDist {SEARCH}")
        result = measure(Operator(messd, args.feed), args.messcap)
    except (ProbeFailed, ConnectionError, OSError) as e:
        print(f"measure_cube: {e}", file=sys.stderr)
        return 1
    if args.json:
        print(json.dumps(result))
    else:
        print(report(result))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
