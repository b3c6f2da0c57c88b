#!/usr/bin/python3
"""Ranks the variants of a slap-noise study (`flexehd sweep` of a case with `acoustics`,
e.g. examples/engine86/study_slap_noise.yaml; docs/acoustics.md) by their equivalent radiated
power.

    /usr/bin/python3 scripts/rank_slap_noise.py STUDY_DIR [--out DIR]

Reads STUDY_DIR/study.csv and prints, per engine speed, the variants from quietest to loudest
with their ERP (dB re 1 pW), rms surface velocity, the power the piston puts into the liner's
vibration and the peak slap energy; writes erp_ranking.png (ERP against the pin offset per
speed, or against the variant number) and erp_ranking.csv into --out (default STUDY_DIR).
Needs only numpy and matplotlib (Agg backend, no display).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ERP = "acoustics.erp_total_db"
COLUMNS = [("acoustics.erp_total_db", "ERP [dB re 1 pW]", 1.0),
           ("acoustics.velocity_rms_m_per_s", "v_rms [mm/s]", 1e3),
           ("acoustics.liner_input_power_w", "P_in [mW]", 1e3),
           ("slap_kinetic_energy_max_j", "slap energy [mJ]", 1e3),
           ("slap_kinetic_energy_max_crank_deg", "at [deg]", 1.0),
           ("periodic", "periodic", None)]


def read_rows(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r.get("status") == "ok"]
    if not rows:
        raise ValueError(f"{path}: no variant finished ok yet")
    if ERP not in rows[0]:
        raise ValueError(f"{path}: no column {ERP}; the study's outputs must collect it")
    return rows


def value(row, key):
    try:
        return float(row.get(key, ""))
    except ValueError:
        return None


def cell(row, key, scale):
    if scale is None:
        return row.get(key, "")
    v = value(row, key)
    return "" if v is None else f"{v * scale:.4g}"


def main():
    parser = argparse.ArgumentParser(description="Rank a slap-noise study's variants by ERP.")
    parser.add_argument("study", metavar="STUDY_DIR")
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    try:
        rows = read_rows(os.path.join(args.study, "study.csv"))
    except (OSError, ValueError) as e:
        print(f"rank_slap_noise: {e}", file=sys.stderr)
        return 2
    out = args.out or args.study
    os.makedirs(out, exist_ok=True)
    speeds = sorted({value(r, "engine.speed_rpm") for r in rows}, key=lambda s: (s is None, s))
    offset = "engine.pin_offset" if "engine.pin_offset" in rows[0] else None
    table = []
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    for speed in speeds:
        group = [r for r in rows if value(r, "engine.speed_rpm") == speed]
        group.sort(key=lambda r: value(r, ERP) if value(r, ERP) is not None else float("inf"))
        print(f"\n{speed:g} rpm, quietest first:" if speed is not None else "\nquietest first:")
        header = ["variant"] + ([offset] if offset else []) + [label for _, label, _ in COLUMNS]
        print("  " + "  ".join(f"{h:>16}" for h in header))
        for rank, r in enumerate(group, 1):
            cells = [r["variant"]] + ([cell(r, offset, 1e3) + " mm"] if offset else [])
            cells += [cell(r, key, scale) for key, _, scale in COLUMNS]
            print("  " + "  ".join(f"{c:>16}" for c in cells))
            table.append({"speed_rpm": speed, "rank": rank, "variant": r["variant"],
                          **({"pin_offset_m": r[offset]} if offset else {}),
                          **{key: r.get(key, "") for key, _, _ in COLUMNS}})
        if offset:
            pts = sorted((value(r, offset), value(r, ERP)) for r in group if value(r, ERP) is not None)
            ax.plot([p[0] * 1e3 for p in pts], [p[1] for p in pts], "o-", label=f"{speed:g} rpm")
    ax.set_xlabel("pin offset towards the major thrust side [mm]" if offset else "variant")
    ax.set_ylabel("ERP [dB re 1 pW]")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "erp_ranking.png"), dpi=120)
    with open(os.path.join(out, "erp_ranking.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0].keys()))
        w.writeheader()
        w.writerows(table)
    print(f"\n{os.path.join(out, 'erp_ranking.png')}, {os.path.join(out, 'erp_ranking.csv')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
