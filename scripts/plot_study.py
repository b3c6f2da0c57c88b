#!/usr/bin/python3
"""Trade-off plots of a design study (`flexehd sweep`, docs/sweep.md).

    /usr/bin/python3 scripts/plot_study.py STUDY_DIR [--color PARAMETER] [--out DIR]

Reads STUDY_DIR/study.csv (the variants finished so far; failed ones are skipped) and writes:
  tradeoff.png    friction power vs slap energy, and FMEP vs the largest lateral excursion,
                  each point a variant coloured by a parameter (the first one by default)
  parameters.png  each collected output against each numeric parameter
Needs only numpy and matplotlib (Agg backend, no display).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

FIXED = {"variant", "id", "status", "run_time_s", "error"}
LABELS = {
    "friction_power_mean_w": "friction power [W]",
    "fmep_pa": "skirt FMEP [kPa]",
    "slap_kinetic_energy_max_j": "slap energy [mJ]",
    "lateral_extreme_m": "max |lateral| [µm]",
    "lateral_min_m": "lateral min [µm]",
    "lateral_max_m": "lateral max [µm]",
    "tilt_min_rad": "tilt min [mrad]",
    "tilt_max_rad": "tilt max [mrad]",
    "min_film_m": "min film [µm]",
    "max_pressure_pa": "max film pressure [MPa]",
    "contact_force_max_n": "max contact force [N]",
}
SCALE = {"fmep_pa": 1e-3, "slap_kinetic_energy_max_j": 1e3, "lateral_extreme_m": 1e6, "lateral_min_m": 1e6,
         "lateral_max_m": 1e6, "tilt_min_rad": 1e3, "tilt_max_rad": 1e3, "min_film_m": 1e6, "max_pressure_pa": 1e-6}


def number(text):
    try:
        v = float(text)
        return v if np.isfinite(v) else None
    except ValueError:
        return None


def read_study(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise ValueError(f"{path}: no finished variants yet")
    header = list(rows[0].keys())
    status = header.index("status")
    params, outputs = header[2:status], [h for h in header[status + 1:] if h not in FIXED]
    ok = [r for r in rows if r["status"] == "ok"]
    if not ok:
        raise ValueError(f"{path}: no variant finished ok")
    data = {}
    for k in params + outputs:
        vals = [number(r[k]) for r in ok]
        if all(v is not None for v in vals):
            data[k] = np.array(vals)
    if "lateral_min_m" in data and "lateral_max_m" in data:
        data["lateral_extreme_m"] = np.maximum(-data["lateral_min_m"], data["lateral_max_m"])
    return params, outputs, data, len(rows) - len(ok)


def scaled(data, key):
    return data[key] * SCALE.get(key, 1.0)


def scatter(ax, data, x, y, color):
    if color in data:
        sc = ax.scatter(scaled(data, x), scaled(data, y), c=data[color], cmap="viridis", s=36, edgecolors="k",
                        linewidths=0.4)
        return sc
    ax.scatter(scaled(data, x), scaled(data, y), s=36)
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("study_dir")
    ap.add_argument("--color", help="parameter that colours the points (default: the first one)")
    ap.add_argument("--out", help="output directory (default: STUDY_DIR/plots)")
    a = ap.parse_args()
    try:
        params, outputs, data, failed = read_study(os.path.join(a.study_dir, "study.csv"))
    except (OSError, ValueError, KeyError) as e:
        print(f"plot_study.py: error: {e}", file=sys.stderr)
        return 1
    if failed:
        print(f"plot_study.py: {failed} failed variant(s) left out", file=sys.stderr)
    color = a.color or (params[0] if params else None)
    if a.color and a.color not in data:
        print(f"plot_study.py: error: --color {a.color} is not a numeric parameter of the study", file=sys.stderr)
        return 1
    out = a.out or os.path.join(a.study_dir, "plots")
    os.makedirs(out, exist_ok=True)

    pairs = [(x, y) for x, y in [("slap_kinetic_energy_max_j", "friction_power_mean_w"),
                                  ("lateral_extreme_m", "fmep_pa")] if x in data and y in data]
    if pairs:
        fig, axes = plt.subplots(1, len(pairs), figsize=(5.5 * len(pairs), 4.5), squeeze=False)
        for ax, (x, y) in zip(axes[0], pairs):
            sc = scatter(ax, data, x, y, color)
            ax.set_xlabel(LABELS.get(x, x))
            ax.set_ylabel(LABELS.get(y, y))
            ax.grid(alpha=0.3)
            if sc is not None:
                fig.colorbar(sc, ax=ax, label=color)
        fig.suptitle("design study: trade-offs (lower left is better)")
        fig.tight_layout()
        fig.savefig(os.path.join(out, "tradeoff.png"), dpi=150)
        plt.close(fig)

    numeric = [p for p in params if p in data]
    shown = [o for o in outputs if o in data and o != "periodic"][:8]
    if numeric and shown:
        fig, axes = plt.subplots(len(shown), len(numeric), figsize=(4.2 * len(numeric), 2.6 * len(shown)),
                                 squeeze=False, sharex="col")
        for i, o in enumerate(shown):
            for j, p in enumerate(numeric):
                other = next((q for q in numeric if q != p), None)
                scatter(axes[i][j], data, p, o, other)
                axes[i][j].set_ylabel(LABELS.get(o, o) if j == 0 else "")
                axes[i][j].grid(alpha=0.3)
                if i == len(shown) - 1:
                    axes[i][j].set_xlabel(p)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "parameters.png"), dpi=120)
        plt.close(fig)
    print(f"plots in {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
