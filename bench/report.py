#!/usr/bin/python3
"""Merges the JSON files the bench programs wrote in one or more runs into one results file,
prints every figure with its value in each run, its reference and ratio, and its goal, and
draws the plots (latency histograms and CDFs, curves) with matplotlib when it is installed.

Usage: report.py --out RESULTS.json [--plots DIR] [--quick] [--machine JSON] RUN_DIR [RUN_DIR...]
Each RUN_DIR holds the *.json files of one run (bench_net.json, bench_rt.json, ...) and any
*.txt output of the text-only benches. --quick draws PNG only (no SVG), without the log axes'
minor ticks, and a distribution that is another's reference (a floor) only beside it, not on
a plot of its own.
Without matplotlib the figures and the results file are written all the same, and a line on
stderr and the results' "plots_unavailable" say why there are no plots.
Exit status 0 when the report was written (with or without plots), 1 when a plot could not
be drawn (the results file is written first), 2 on bad input (a file that is not the
benches' JSON names the file and the key).
"""
import argparse
import glob
import json
import math
import os
import sys


def load_run(run_dir):
    """{bench name: its JSON object} and {bench name: text output} of one run directory."""
    benches, texts = {}, {}
    for path in sorted(glob.glob(os.path.join(run_dir, "*.json"))):
        try:
            with open(path, encoding="utf-8") as f:
                data = json.load(f)
        except (OSError, ValueError) as e:
            raise SystemExit(f"report.py: {path}: not readable JSON ({e})")
        if not isinstance(data, dict) or not isinstance(data.get("figures"), list):
            raise SystemExit(f"report.py: {path}: expected an object with a 'figures' list")
        for i, fig in enumerate(data["figures"]):
            for key in ("id", "what", "unit"):
                if key not in fig:
                    raise SystemExit(f"report.py: {path}: figures[{i}].{key} missing")
        benches[data.get("bench", os.path.basename(path)[:-5])] = data
    for path in sorted(glob.glob(os.path.join(run_dir, "*.txt"))):
        with open(path, encoding="utf-8", errors="replace") as f:
            texts[os.path.basename(path)[:-4]] = f.read()
    return benches, texts


def number(v, unit=""):
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "—"
    text = f"{v:.3g}" if abs(v) < 1000 else f"{v:.0f}"
    return f"{text} {unit}".strip()


def print_summary(runs):
    """One line per figure: the value in every run, the ratios, the goal and whether all runs met it."""
    order, seen = [], {}
    for benches, _ in runs:
        for bench in benches.values():
            for fig in bench["figures"]:
                if fig["id"] not in seen:
                    seen[fig["id"]] = fig
                    order.append(fig["id"])
    width = max((len(i) for i in order), default=10)
    for fid in order:
        fig = seen[fid]
        values, ratios, met = [], [], []
        for benches, _ in runs:
            found = next((f for b in benches.values() for f in b["figures"] if f["id"] == fid), None)
            if found is None:
                values.append("—")
                continue
            values.append(number(found.get("value"), found["unit"]))
            if found.get("ratio") is not None:
                ratios.append(f"x{found['ratio']:.2f}")
            if found.get("met") is not None:
                met.append(bool(found["met"]))
        line = f"{fid:<{width}}  {' | '.join(values):<24}"
        if fig.get("reference_id"):
            line += f"  vs {fig['reference_id']}: {' | '.join(ratios) or '—'}"
        if fig.get("goal"):
            verdict = "met" if met and all(met) else ("NOT met" if met else "—")
            line += f"  goal {fig['goal']}: {verdict}"
        if fig.get("virtual_time"):
            line += "  (virtual time)"
        print(line)
        print(f"{'':<{width}}  {fig['what']}")


def clean(dist):
    """The distribution's samples that are numbers, sorted."""
    return sorted(s for s in dist.get("samples", []) if isinstance(s, (int, float)) and math.isfinite(s))


def save(plt, fig, plots_dir, name, formats, quick):
    """Writes the figure in each of `formats` (png, svg); returns the paths. quick: without the
    log axes' minor ticks (laying them out is most of a plot's cost)."""
    if quick:
        for ax in fig.axes:
            ax.minorticks_off()
    fig.tight_layout()
    paths = [os.path.join(plots_dir, f"{name}.{ext}") for ext in formats]
    for path in paths:
        fig.savefig(path)
    plt.close(fig)
    return paths


def load_pyplot():
    """matplotlib's pyplot on the Agg backend, or None when matplotlib is not installed."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return None
    return plt


def plot(plt, runs, plots_dir, quick):
    """Draws every run's distributions and curves into plots_dir; returns the paths written.
    quick: PNG only, no minor ticks, and a distribution another one shows as its reference is
    not drawn alone."""
    formats = ("png",) if quick else ("png", "svg")
    os.makedirs(plots_dir, exist_ok=True)
    written = []
    for run_index, (benches, _) in enumerate(runs, start=1):
        for bench_name, bench in benches.items():
            by_id = {d["id"]: d for d in bench.get("distributions", [])}
            shown_beside = {d.get("reference_id") for d in bench.get("distributions", []) if clean(d)}
            for dist in bench.get("distributions", []):
                if not clean(dist) or (quick and dist["id"] in shown_beside):
                    continue
                shown = [(dist, "#4477aa")]
                ref = by_id.get(dist.get("reference_id") or "")
                if ref is not None and clean(ref):
                    shown.append((ref, "#cc6677"))
                everything = [s for d, _ in shown for s in clean(d)]
                fig, (hist, tail) = plt.subplots(1, 2, figsize=(11, 4))
                positive = [s for s in everything if s > 0]
                bins = 60
                if positive and max(positive) / min(positive) > 50:
                    lo, hi = math.log10(min(positive)), math.log10(max(positive))
                    bins = [10 ** (lo + (hi - lo) * i / 60) for i in range(61)]
                    hist.set_xscale("log")
                    tail.set_xscale("log")
                for d, colour in shown:
                    samples = clean(d)
                    n = len(samples)
                    label = f"{d['id']} ({n})"
                    hist.hist(samples, bins=bins, histtype="stepfilled", color=colour, alpha=0.6, label=label)  # one patch, not 60 bars: the same look, cheaper
                    # the tail: the fraction of samples above x, down to one sample
                    tail.step(samples, [1 - i / n for i in range(n)], where="post", color=colour, label=label)
                hist.set_yscale("log")
                hist.set_xlabel(dist.get("unit", ""))
                hist.set_ylabel("count")
                hist.legend(fontsize=7)
                tail.set_yscale("log")
                for p in (0.5, 0.01, 0.001):
                    tail.axhline(p, color="#bbbbbb", linewidth=0.6)
                tail.set_xlabel(dist.get("unit", ""))
                tail.set_ylabel("fraction above x (p50, p99, p99.9 lines)")
                fig.suptitle(f"{dist.get('what', dist['id'])} (run {run_index})", fontsize=9)
                written += save(plt, fig, plots_dir, f"{dist['id']}.run{run_index}", formats, quick)
            for curve in bench.get("curves", []):
                fig, ax = plt.subplots(figsize=(6, 4))
                for name, points in curve.get("series", {}).items():
                    if points:
                        xs, ys = zip(*points)
                        ax.plot(xs, ys, marker="o", label=name)
                ax.set_xlabel(curve.get("x", ""))
                ax.set_ylabel(curve.get("y", ""))
                if any(p[0] > 0 for s in curve.get("series", {}).values() for p in s):
                    ax.set_xscale("log")
                ax.legend()
                ax.set_title(f"{curve.get('what', curve['id'])} (run {run_index})", fontsize=9)
                written += save(plt, fig, plots_dir, f"{curve['id']}.run{run_index}", formats, quick)
    return written


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", required=True, help="the merged results file to write")
    parser.add_argument("--plots", help="directory for the PNG/SVG plots")
    parser.add_argument("--quick", action="store_true", help="PNG only, floors only beside what they are the reference of")
    parser.add_argument("--machine", help="JSON object describing the machine (cores, kernel, load)")
    parser.add_argument("runs", nargs="+", help="one directory per run")
    args = parser.parse_args()
    runs = [load_run(d) for d in args.runs]
    machine = {}
    if args.machine:
        try:
            machine = json.loads(args.machine)
        except ValueError as e:
            print(f"report.py: --machine: not JSON ({e})", file=sys.stderr)
            return 2
    print_summary(runs)
    written, unavailable, failed = [], None, None
    if args.plots:
        plt = load_pyplot()
        if plt is None:
            unavailable = "python3-matplotlib is not installed (Debian: apt-get install python3-matplotlib)"
        else:
            try:
                written = plot(plt, runs, args.plots, args.quick)
            except Exception as e:  # matplotlib's own errors vary by version: say which, keep the figures
                failed = f"{type(e).__name__}: {e}"
    result = {"machine": machine, "runs": [{"benches": b, "text": t} for b, t in runs], "plots": written}
    if unavailable or failed:
        result["plots_unavailable"] = unavailable or f"plotting failed: {failed}"
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w", encoding="utf-8") as f:
        json.dump(result, f, indent=1)
    print(f"\nresults: {args.out}" + (f"  plots: {args.plots} ({len(written)} files)" if written else ""))
    if unavailable:
        print(f"report.py: no plots: {unavailable}; the figures above and the results file are complete", file=sys.stderr)
    if failed:
        print(f"report.py: plotting failed after {len(written)} files ({failed}); the figures above and the results file are complete",
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
