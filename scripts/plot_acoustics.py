#!/usr/bin/python3
"""Plots the slap-noise figures of a flexehd run (acoustics.csv, acoustics_spectrum.csv,
acoustics_map.csv, written by `flexehd acoustics RESULTS_DIR` or by a run with the case's
`acoustics` section; docs/acoustics.md §9) as PNG figures.

    /usr/bin/python3 scripts/plot_acoustics.py RESULTS_DIR [--out DIR]

Writes, into --out (default RESULTS_DIR/plots_acoustics):

  erp_spectrum.png  the liner's equivalent radiated power (dB re 1 pW) per 1/3-octave band (bars)
                    and per spectral bin (line) over frequency, with the strongest engine orders
                    marked from acoustics.json
  erp_map.png       the band power (dB re 1 pW) over crank angle (frame centres, 0-720 deg) and
                    the 1/3-octave bands (blank where a band is narrower than a frame's bin)

Needs numpy and matplotlib (Debian: python3-numpy, python3-matplotlib). Without the CSV files it
prints a note and exits 0.
"""
import argparse
import csv
import json
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

from plot_results import save  # noqa: E402  (the PNG written atomically, as every plot here)


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) if r[k] != "" else np.nan for r in rows]) for k in rows[0]} if rows else {}


def level_db(power_w):
    with np.errstate(divide="ignore"):
        return np.where(power_w > 0.0, 10.0 * np.log10(np.maximum(power_w, 1e-300) / 1e-12), np.nan)


def plot_spectrum(bands, spectrum, doc, out_dir):
    fig, ax = plt.subplots(figsize=(9, 5))
    positive = spectrum["frequency_hz"] > 0.0
    ax.semilogx(spectrum["frequency_hz"][positive], level_db(spectrum["erp_w"][positive]), color="0.55", lw=0.8,
                label=f"per bin ({doc['record']['bin_hz']:.3g} Hz, {doc['record']['window']} window)")
    widths = bands["band_upper_hz"] - bands["band_lower_hz"]
    ax.bar(bands["band_lower_hz"], level_db(bands["erp_w"]), width=widths, align="edge", alpha=0.55,
           color="C0", edgecolor="C0", label="1/3-octave bands")
    for k, line in enumerate(doc["erp"]["orders"][:3]):
        if line["erp_db"] is not None:
            ax.annotate(f"order {line['order']:g}", (line["frequency_hz"], line["erp_db"]), fontsize=8,
                        xytext=(0, 8 + 11 * k), textcoords="offset points", ha="center", color="C3",
                        arrowprops={"arrowstyle": "-", "color": "C3", "lw": 0.5})
    low, high = ax.get_ylim()
    ax.set_ylim(low, high + 12.0)  # room for the order labels above the bars
    total = doc["erp"]["total_db"]
    ax.set_title(f"Liner ERP, surface '{doc['record']['surface']}', cycle {doc['record']['cycle']}: total "
                 + (f"{total:.1f} dB re 1 pW" if total is not None else "0 W") + f" up to {doc['record']['up_to_hz']:g} Hz")
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("equivalent radiated power (dB re 1 pW)")
    ax.set_xlim(max(1.0, bands["band_lower_hz"].min()), doc["record"]["up_to_hz"] * 1.12)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    save(fig, out_dir, "erp_spectrum.png")


def plot_map(cells, doc, out_dir):
    angles = np.unique(cells["crank_deg"])
    mids = np.unique(cells["band_mid_hz"])
    grid = np.full((len(mids), len(angles)), np.nan)
    ia = np.searchsorted(angles, cells["crank_deg"])
    im = np.searchsorted(mids, cells["band_mid_hz"])
    grid[im, ia] = level_db(cells["erp_w"])
    fig, ax = plt.subplots(figsize=(9, 5))
    mesh = ax.pcolormesh(angles, mids, grid, shading="nearest", cmap="magma")
    ax.set_yscale("log")
    ax.set_xlabel("crank angle (deg, frame centres; 360 = firing TDC)")
    ax.set_ylabel("1/3-octave band mid frequency (Hz)")
    ax.set_title(f"Liner ERP over the cycle (frames of {doc['map']['frame_deg']:.3g} deg; "
                 "blank: bands narrower than a frame's bin)")
    fig.colorbar(mesh, ax=ax, label="ERP (dB re 1 pW)")
    fig.tight_layout()
    save(fig, out_dir, "erp_map.png")


def main(argv=None):
    parser = argparse.ArgumentParser(description="Plot a flexehd run's slap-noise figures (acoustics*.csv) as PNG.")
    parser.add_argument("results", metavar="RESULTS_DIR", help="results directory holding acoustics.json and its CSVs")
    parser.add_argument("--out", help="output folder (default RESULTS_DIR/plots_acoustics)")
    a = parser.parse_args(argv)
    paths = {name: os.path.join(a.results, name)
             for name in ("acoustics.json", "acoustics.csv", "acoustics_spectrum.csv", "acoustics_map.csv")}
    missing = [n for n, p in paths.items() if not os.path.isfile(p)]
    if missing:
        print(f"plot_acoustics.py: note: {a.results} has no {', '.join(missing)} (run `flexehd acoustics "
              f"{a.results}`, or a case with an `acoustics` section): nothing to plot")
        return 0
    with open(paths["acoustics.json"]) as f:
        doc = json.load(f)
    out_dir = a.out or os.path.join(a.results, "plots_acoustics")
    os.makedirs(out_dir, exist_ok=True)
    plot_spectrum(read_csv(paths["acoustics.csv"]), read_csv(paths["acoustics_spectrum.csv"]), doc, out_dir)
    plot_map(read_csv(paths["acoustics_map.csv"]), doc, out_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
