#!/usr/bin/python3
"""Operating-map plots of a speed x load study (`flexehd sweep`, docs/sweep.md).

    /usr/bin/python3 scripts/plot_map.py STUDY_DIR [--out DIR]

Reads STUDY_DIR/study.csv of a study whose parameters are engine.speed_rpm and
cylinder_pressure (one pressure-trace file per load point, as in
examples/engine86/study_speed_load.yaml) and writes map.png: skirt friction power, minimum
film thickness (the true gap: below zero the surfaces overlap and the hard contact carries
the load) and peak slap kinetic energy over speed, one line per load point, as engine maps are
read. A third parameter (e.g. lubricant.supply in study_oil_supply.yaml) gives each of its
values a line style, the load points keeping their colours; a variant that did not become
periodic is drawn as an open marker. Failed variants are left out and listed. Needs only numpy
and matplotlib (Agg backend).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PANELS = [("friction_power_mean_w", "skirt friction power [W]", 1.0),
          ("min_film_m", "minimum film (gap) [µm]", 1e6),
          ("slap_kinetic_energy_max_j", "peak slap kinetic energy [mJ]", 1e3)]


def load_label(path):
    name = os.path.splitext(os.path.basename(path))[0]
    for key, label in (("motored", "motored"), ("full", "full load")):
        if key in name:
            return label
    return "part load" if name == "cylinder_pressure" else name


STYLES = ["-", "--", ":", "-."]


def third_parameter(row):
    """The study's parameter column besides speed and load (None when there is none)."""
    keys = list(row.keys())
    params = keys[keys.index("id") + 1:keys.index("status")] if "id" in keys and "status" in keys else []
    others = [k for k in params if k not in ("engine.speed_rpm", "cylinder_pressure")]
    return others[0] if len(others) == 1 else None


def value_label(parameter, value):
    """A short legend text for a value of the third parameter."""
    if parameter == "lubricant.supply":
        if "liner_layer" in value:
            return "starved (liner layer)"
        return "flooded"
    return value if len(value) <= 30 else value[:27] + "..."


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("study", help="the study directory (holds study.csv)")
    ap.add_argument("--out", help="directory for map.png (default: the study directory)")
    args = ap.parse_args()
    path = os.path.join(args.study, "study.csv")
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        print(f"plot_map: cannot read {path}: {e.strerror}", file=sys.stderr)
        return 1
    for key in ("engine.speed_rpm", "cylinder_pressure", "status"):
        if not rows or key not in rows[0]:
            print(f"plot_map: {path} has no column '{key}' (a speed x load study is expected)", file=sys.stderr)
            return 1
    failed = [r for r in rows if r["status"] != "ok"]
    third = third_parameter(rows[0])
    lines = {}
    for r in rows:
        if r["status"] != "ok":
            continue
        lines.setdefault((load_label(r["cylinder_pressure"]), r[third] if third else ""), []).append(r)
    if not lines:
        print(f"plot_map: {path}: no variant finished ok", file=sys.stderr)
        return 1
    fig, axes = plt.subplots(1, len(PANELS), figsize=(5 * len(PANELS), 4))
    order = {"motored": 0, "part load": 1, "full load": 2}
    loads = sorted({k[0] for k in lines}, key=lambda n: (order.get(n, 3), n))
    values = sorted({k[1] for k in lines}, key=lambda v: [r[third] for r in rows].index(v) if third else 0)
    colours = {n: f"C{i}" for i, n in enumerate(loads)}
    styles = {v: STYLES[i % len(STYLES)] for i, v in enumerate(values)}
    for ax, (key, label, scale) in zip(axes, PANELS):
        for (name, value), rs in sorted(lines.items(), key=lambda kv: (order.get(kv[0][0], 3), kv[0][0],
                                                                        values.index(kv[0][1]))):
            rs = sorted(rs, key=lambda r: float(r["engine.speed_rpm"]))
            x = np.array([float(r["engine.speed_rpm"]) for r in rs])
            y = np.array([float(r[key]) * scale for r in rs])
            text = name + (", " + value_label(third, value) if third else "")
            ax.plot(x, y, styles[value], color=colours[name], label=text)
            periodic = np.array([r.get("periodic", "true") == "true" for r in rs])
            ax.plot(x[periodic], y[periodic], "o", color=colours[name])
            ax.plot(x[~periodic], y[~periodic], "o", mfc="w", color=colours[name])
        if key == "min_film_m":
            ax.axhline(0.0, color="k", lw=0.8)
        ax.set_xlabel("engine speed [rpm]")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=7)
    title = "operating map (open markers: not periodic within the tolerance)"
    if failed:
        title += "; failed: " + ", ".join(
            f"{r['engine.speed_rpm']} rpm {load_label(r['cylinder_pressure'])}"
            + (f" {value_label(third, r[third])}" if third else "") for r in failed)
    fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    out = args.out or args.study
    os.makedirs(out, exist_ok=True)
    fig.savefig(os.path.join(out, "map.png"), dpi=120)
    print(f"wrote {os.path.join(out, 'map.png')} ({sum(len(v) for v in lines.values())} points, {len(failed)} failed)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
