#!/usr/bin/python3
"""Plots the history of a flexehd run (history.csv in a results directory) as PNG figures.

    /usr/bin/python3 scripts/plot_results.py RESULTS_DIR [--compare OTHER_DIR ...]
                                             [--labels HD EHD ...] [--cycle N] [--out DIR]

Uses the last complete engine cycle of each run (the `cycle` column; --cycle picks another)
and writes, into --out (default RESULTS_DIR/plots):

  secondary_motion.png  lateral displacement (um), tilt (deg) and side force (kN) over the
                        crank angle, runs overlaid (HD vs EHD, like Fig. 5 of Dlugos et al. 2016)
  friction.png          friction force (N) and friction power (W), with cycle averages
  film.png              minimum film thickness (um) and maximum film pressure (MPa)

Needs only numpy and matplotlib (Debian: python3-numpy, python3-matplotlib). Column names,
units and sign conventions: docs/results-format.md.
"""
import argparse
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

REQUIRED = ["cycle", "crank_deg", "time_s", "lateral_m", "tilt_rad", "side_force_n",
            "friction_force_n", "friction_power_w", "min_film_m", "max_pressure_pa"]
STYLES = ["-", "--", "-.", ":"]
COLORS = ["tab:blue", "tab:red", "tab:green", "tab:purple"]


class PlotError(Exception):
    pass


def read_history(directory):
    """Columns of RESULTS_DIR/history.csv as float arrays, by header name."""
    if not os.path.isdir(directory):
        raise PlotError(f"'{directory}' is not a directory (expected a flexehd results directory)")
    path = os.path.join(directory, "history.csv")
    if not os.path.isfile(path):
        raise PlotError(f"'{path}' does not exist: is '{directory}' the results directory of a flexehd run?")
    with open(path, newline="") as f:
        text = f.read()
    lines = text.split("\n")
    partial = lines.pop()  # "" when the file ends with a newline
    if partial.strip():
        print(f"plot_results.py: warning: '{path}': ignoring the unfinished last line (run still going "
              f"or killed)", file=sys.stderr)
    header, rows = None, []
    for number, line in enumerate(lines, start=1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        fields = [s.strip() for s in line.split(",")]
        if header is None:
            header = fields
            continue
        if len(fields) != len(header):
            raise PlotError(f"'{path}' line {number}: {len(fields)} values, the header has {len(header)} columns")
        try:
            rows.append([float(v) for v in fields])
        except ValueError as e:
            raise PlotError(f"'{path}' line {number}: {e}") from None
    if header is None:
        raise PlotError(f"'{path}' is empty (no header line)")
    missing = [c for c in REQUIRED if c not in header]
    if missing:
        raise PlotError(f"'{path}': the header lacks the column(s) {', '.join(repr(c) for c in missing)}; "
                        f"is this a flexehd history.csv?")
    if not rows:
        raise PlotError(f"'{path}' has a header but no data rows yet")
    data = np.array(rows, dtype=float)
    if not np.all(np.isfinite(data)):
        raise PlotError(f"'{path}' holds non-finite values")
    return path, {name: data[:, k] for k, name in enumerate(header)}


def cycle_complete(h, c, cycles):
    """A cycle is complete when a later one has started or its steps cover (almost) 720 deg.

    crank_deg is the true crank angle: with time.start_deg > 0 a cycle runs from start_deg to
    720 and on from 0, so the degrees covered are the sum of the steps, not the largest angle."""
    if c < cycles.max():
        return True
    mask = h["cycle"] == c
    if "step_deg" not in h:
        return h["crank_deg"][mask].max() >= 719.0
    steps = h["step_deg"][mask]
    return steps.sum() >= 720.0 - max(1.5 * steps.max(), 1.0)


def select_cycle(path, h, wanted):
    cycles = np.unique(h["cycle"]).astype(int)
    if wanted is not None:
        if wanted not in cycles:
            raise PlotError(f"'{path}' has no cycle {wanted} (cycles {cycles.min()}..{cycles.max()})")
        c, note = wanted, ""
    else:
        complete = [c for c in cycles if cycle_complete(h, c, cycles)]
        if complete:
            c, note = complete[-1], ""
        else:
            c, note = cycles.max(), " (incomplete)"
            print(f"plot_results.py: warning: '{path}': no complete cycle yet, plotting the partial cycle {c}",
                  file=sys.stderr)
    mask = h["cycle"] == c
    sel = {k: v[mask] for k, v in h.items()}
    order = np.argsort(sel["crank_deg"], kind="stable")
    return {k: v[order] for k, v in sel.items()}, int(c), note


def cycle_mean(sel, column):
    """Time average of a column over the selected rows (steps are not uniform)."""
    t, y = sel["time_s"], sel[column]
    if len(t) < 2 or t[-1] <= t[0]:
        return float(np.mean(y))
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(t)) / (t[-1] - t[0]))


def decorate_crank_axis(axes):
    for ax in axes:
        ax.set_xlim(0, 720)
        ax.set_xticks(np.arange(0, 721, 90))
        ax.grid(True, alpha=0.3)
        for x in (180, 540):
            ax.axvline(x, color="0.6", lw=0.6, ls=":")
        ax.axvline(360, color="0.4", lw=0.8, ls="--")
        ax.axhline(0, color="0.5", lw=0.5)
    top = axes[0]
    for x, name in ((0, "TDC"), (180, "BDC"), (360, "firing TDC"), (540, "BDC"), (720, "TDC")):
        top.annotate(name, (x, 1.0), xycoords=("data", "axes fraction"), xytext=(0, 2),
                     textcoords="offset points", ha="center", va="bottom", fontsize=7, color="0.3")
    axes[-1].set_xlabel("crank angle (deg)")


def save(fig, out_dir, name):
    path = os.path.join(out_dir, name)
    tmp = path + ".tmp"
    fig.savefig(tmp, dpi=150, format="png")
    plt.close(fig)
    os.replace(tmp, path)
    print(path)


def plot_secondary_motion(runs, out_dir):
    fig, axes = plt.subplots(3, 1, sharex=True, figsize=(9, 8.5),
                             gridspec_kw={"height_ratios": [1.2, 1.2, 0.9]})
    for k, (label, sel, _) in enumerate(runs):
        style = dict(color=COLORS[k % len(COLORS)], ls=STYLES[k % len(STYLES)], lw=1.3)
        axes[0].plot(sel["crank_deg"], sel["lateral_m"] * 1e6, label=label, **style)
        axes[1].plot(sel["crank_deg"], np.degrees(sel["tilt_rad"]), label=label, **style)
        axes[2].plot(sel["crank_deg"], sel["side_force_n"] * 1e-3, label=label, **style)
    axes[0].set_ylabel("lateral displacement (µm)\n+ = major thrust side")
    axes[1].set_ylabel("tilt (deg)\n+ = top towards thrust side")
    axes[2].set_ylabel("side force (kN)")
    axes[0].set_title("Piston secondary motion" + cycle_note(runs), pad=14)
    for ax in axes:
        ax.legend(loc="best", fontsize=8)
    decorate_crank_axis(axes)
    fig.tight_layout()
    save(fig, out_dir, "secondary_motion.png")


def plot_friction(runs, out_dir):
    fig, axes = plt.subplots(2, 1, sharex=True, figsize=(9, 6.5))
    for k, (label, sel, _) in enumerate(runs):
        style = dict(color=COLORS[k % len(COLORS)], ls=STYLES[k % len(STYLES)], lw=1.3)
        axes[0].plot(sel["crank_deg"], sel["friction_force_n"],
                     label=label, **style)
        mean_power = cycle_mean(sel, "friction_power_w")
        axes[1].plot(sel["crank_deg"], sel["friction_power_w"],
                     label=f"{label} (cycle mean {mean_power:.1f} W)", **style)
        axes[1].axhline(mean_power, color=style["color"], lw=0.8, ls=":")
    axes[0].set_ylabel("friction force on the piston (N)\n+ = towards the head")
    axes[1].set_ylabel("friction power loss (W)")
    axes[0].set_title("Skirt friction" + cycle_note(runs), pad=14)
    for ax in axes:
        ax.legend(loc="best", fontsize=8)
    decorate_crank_axis(axes)
    fig.tight_layout()
    save(fig, out_dir, "friction.png")


def plot_film(runs, out_dir):
    fig, axes = plt.subplots(2, 1, sharex=True, figsize=(9, 6.5))
    for k, (label, sel, _) in enumerate(runs):
        style = dict(color=COLORS[k % len(COLORS)], ls=STYLES[k % len(STYLES)], lw=1.3)
        axes[0].plot(sel["crank_deg"], sel["min_film_m"] * 1e6, label=label, **style)
        axes[1].plot(sel["crank_deg"], sel["max_pressure_pa"] * 1e-6, label=label, **style)
    axes[0].set_ylabel("minimum film thickness (µm)")
    axes[0].set_ylim(bottom=0)
    axes[1].set_ylabel("maximum film pressure (MPa, gauge)")
    axes[0].set_title("Oil film" + cycle_note(runs), pad=14)
    for ax in axes:
        ax.legend(loc="best", fontsize=8)
    decorate_crank_axis(axes)
    fig.tight_layout()
    save(fig, out_dir, "film.png")


def cycle_note(runs):
    cycles = {f"{c}{note}" for _, _, (c, note) in runs}
    return f", cycle {cycles.pop()}" if len(cycles) == 1 else ", cycles " + ", ".join(
        f"{label}: {c}{note}" for label, _, (c, note) in runs)


def main(argv=None):
    parser = argparse.ArgumentParser(
        description="Plot history.csv of flexehd results directories as PNG figures "
                    "(secondary motion, friction, film).")
    parser.add_argument("results", metavar="RESULTS_DIR", help="results directory of a run (holds history.csv)")
    parser.add_argument("--compare", metavar="OTHER_RESULTS_DIR", nargs="+", default=[],
                        help="results directories of further runs, overlaid (e.g. EHD against HD)")
    parser.add_argument("--labels", nargs="+", metavar="LABEL",
                        help="one legend label per run, RESULTS_DIR first (default: directory names)")
    parser.add_argument("--cycle", type=int, help="cycle to plot (default: the last complete one)")
    parser.add_argument("--out", metavar="DIR", help="directory for the PNGs (default: RESULTS_DIR/plots)")
    args = parser.parse_args(argv)

    dirs = [args.results] + args.compare
    labels = args.labels or [os.path.basename(os.path.normpath(d)) or d for d in dirs]
    try:
        if len(labels) != len(dirs):
            raise PlotError(f"--labels gives {len(labels)} labels for {len(dirs)} runs")
        runs = []
        for label, d in zip(labels, dirs):
            path, h = read_history(d)
            sel, c, note = select_cycle(path, h, args.cycle)
            runs.append((label, sel, (c, note)))
        out_dir = args.out or os.path.join(args.results, "plots")
        try:
            os.makedirs(out_dir, exist_ok=True)
        except OSError as e:
            raise PlotError(f"cannot create the output directory '{out_dir}': {e.strerror}") from None
        plot_secondary_motion(runs, out_dir)
        plot_friction(runs, out_dir)
        plot_film(runs, out_dir)
    except (PlotError, OSError) as e:
        print(f"plot_results.py: error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
