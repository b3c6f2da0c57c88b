#!/usr/bin/python3
"""Plots the Archard wear maps of a flexehd run (wear_piston.vts, wear_liner.vts) as a PNG figure.

    /usr/bin/python3 scripts/plot_wear.py RESULTS_DIR [--out DIR] [--log DECADES]

A run writes the maps into its results directory when the case turns wear on
(contact.piston_wear_coefficient or liner_wear_coefficient > 0; docs/coupling.md §7): the last
complete cycle's mean wear depth rate `wear_rate_m_per_h`, the skirt's on its film grid in the
piston frame (θ × z, pin axis at z = 0, z towards the crown), the liner's per cell in the liner
frame (θ × z, deck at z = 0, the bore along −z). Writes, into --out (default
RESULTS_DIR/plots_wear):

  wear_maps.png  the skirt's and the liner's mean wear rate (nm/h) over θ (deg, 0 the major thrust
                 side) and the piston-frame z (mm), resp. the depth below the deck (mm, downwards),
                 each with its largest rate marked (circle, value and place); colours linear
                 from 0, or with --log over that many decades below each map's largest rate

The wear files do not mark where the skirt's grid has no skirt (void nodes hold a rate of 0);
when RESULTS_DIR has film snapshots (film.pvd) on the same grid, their `node_kind` (2 = void)
blanks those nodes on the skirt's map and the columns without any skirt on the liner's. The
largest rates are cross-checked against summary.json's `wear` object when it is there.

Needs numpy, matplotlib and VTK's Python modules (Debian: python3-numpy, python3-matplotlib,
python3-vtk9); without VTK or without the wear files it prints a note and exits 0. File formats:
docs/results-format.md.
"""
import argparse
import json
import os
import re
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

from plot_results import save  # noqa: E402  (the PNG written atomically, as every plot here)

ARRAY = "wear_rate_m_per_h"
FILES = (("piston", "wear_piston.vts"), ("liner", "wear_liner.vts"))


class PlotError(Exception):
    pass


class Note(Exception):
    """Nothing to plot, for a reason that is not an error (exit 0)."""


def vtk_modules():
    try:
        from vtkmodules.vtkIOXML import vtkXMLStructuredGridReader
        from vtkmodules.util.numpy_support import vtk_to_numpy
    except ImportError:
        raise Note("the wear maps need VTK's Python modules (Debian python3-vtk9: "
                   "bash scripts/install_deps.sh --with-python): no wear_maps.png") from None
    return vtkXMLStructuredGridReader, vtk_to_numpy


def read_grid(path, arrays):
    """Points (ny, nx, 3) and the named point (or cell) arrays of a .vts, rows = the grid's second
    index (axial), columns = its first (θ)."""
    reader_class, vtk_to_numpy = vtk_modules()
    reader = reader_class()
    reader.SetFileName(path)
    shown = reader.GetGlobalWarningDisplay()
    reader.GlobalWarningDisplayOff()  # a broken file gets one clear line below, not VTK's log
    try:
        reader.Update()
    finally:
        reader.SetGlobalWarningDisplay(shown)
    grid = reader.GetOutput()
    dims = grid.GetDimensions()
    if grid.GetNumberOfPoints() == 0 or dims[2] != 1 or dims[0] < 2 or dims[1] < 1:
        raise PlotError(f"'{path}' is not a readable 2-D VTK structured grid (dimensions {tuple(dims)})")
    nx, ny = dims[0], dims[1]
    xyz = vtk_to_numpy(grid.GetPoints().GetData()).reshape(ny, nx, 3)
    out = {}
    for name in arrays:
        a = grid.GetPointData().GetArray(name)
        if a is not None:
            out[name] = np.asarray(vtk_to_numpy(a), dtype=float).reshape(ny, nx)
            continue
        a = grid.GetCellData().GetArray(name)
        if a is None:
            raise PlotError(f"'{path}' has no point or cell array '{name}'")
        cells = np.asarray(vtk_to_numpy(a), dtype=float).reshape(max(ny - 1, 1), nx - 1)
        # Cell values onto the points (nearest cell), so that both maps draw the same way.
        cols = np.minimum(np.arange(nx), nx - 2)
        rows = np.minimum(np.arange(ny), max(ny - 2, 0))
        out[name] = cells[np.ix_(rows, cols)]
    return xyz, out


def unwrapped_theta(xyz):
    """θ (deg) of the columns, measured from +x about +z, unwrapped. A full circumference (the
    first column repeated as the last) runs from the first column's θ in [0, 360) over 360°; an
    open arc is placed with its middle in [-90, 270) (the thrust (0) and antithrust (180) sides
    each in one piece, as plot_results.py's film maps)."""
    theta = np.degrees(np.unwrap(np.arctan2(xyz[0, :, 1], xyz[0, :, 0])))
    periodic = len(theta) > 2 and np.allclose(xyz[0, 0, :2], xyz[0, -1, :2], rtol=0, atol=1e-12) \
        and abs(theta[-1] - theta[0]) > 180.0
    if periodic:
        theta = theta - 360.0 * np.floor(theta[0] / 360.0)
    else:
        middle = 0.5 * (theta[0] + theta[-1])
        theta = theta - 360.0 * np.floor((middle + 90.0) / 360.0)
    return theta, periodic


def void_mask(directory, piston_xyz):
    """node_kind == 2 (no skirt) of the film snapshots on the skirt's grid as a boolean (ny, nx)
    array, or None (with the reason) when RESULTS_DIR has none on the same grid."""
    pvd = os.path.join(directory, "film.pvd")
    if not os.path.isfile(pvd):
        return None, "no film.pvd"
    with open(pvd) as f:
        files = [os.path.join(directory, n) for n in re.findall(r'file="([^"]+)"', f.read())]
    files = [p for p in files if os.path.isfile(p)]
    if not files:
        return None, "film.pvd lists no snapshot that exists"
    try:
        xyz, arrays = read_grid(files[0], ["node_kind"])
    except PlotError as e:
        return None, str(e)
    if xyz.shape != piston_xyz.shape:
        return None, f"the film snapshots' grid ({xyz.shape[1]} × {xyz.shape[0]}) is not the wear map's " \
                     f"({piston_xyz.shape[1]} × {piston_xyz.shape[0]})"
    # Same θ columns and the same axial rows up to the snapshot's placement (a translation).
    dtheta = np.degrees(np.arctan2(xyz[0, :, 1], xyz[0, :, 0]) - np.arctan2(piston_xyz[0, :, 1], piston_xyz[0, :, 0]))
    dz = xyz[:, 0, 2] - piston_xyz[:, 0, 2]
    if np.max(np.abs((dtheta + 180.0) % 360.0 - 180.0)) > 1e-6 or np.ptp(dz) > 1e-7:
        return None, "the film snapshots' grid is not the wear map's"
    return arrays["node_kind"] == 2, None


def read_map(directory, surface, name):
    path = os.path.join(directory, name)
    xyz, arrays = read_grid(path, [ARRAY])
    rate = arrays[ARRAY]
    theta, periodic = unwrapped_theta(xyz)
    z = xyz[:, 0, 2]
    bad = ~np.isfinite(rate)
    if bad.any():
        print(f"plot_wear.py: warning: '{path}': {int(bad.sum())} non-finite value(s), left blank", file=sys.stderr)
    return {"surface": surface, "path": path, "xyz": xyz, "rate": rate, "theta": theta, "z": z,
            "periodic": periodic, "blank": bad.copy()}


def maximum(m):
    """The largest rate and where, the first in the file's order (as summary.json's)."""
    r = np.where(m["blank"], -np.inf, m["rate"])
    k = int(np.argmax(r))
    i, j = divmod(k, r.shape[1])
    if not np.isfinite(r[i, j]) or r[i, j] <= 0.0:
        return None
    return r[i, j], i, j


def summary_wear(directory):
    try:
        with open(os.path.join(directory, "summary.json")) as f:
            d = json.load(f)
    except (OSError, ValueError):
        return None, None
    w = d.get("wear") if isinstance(d, dict) else None
    return (w if isinstance(w, dict) else None), (d.get("name") if isinstance(d, dict) else None)


def angle_apart(a, b):
    return abs((a - b + 180.0) % 360.0 - 180.0)


def cross_check(m, peak, wear):
    """Warns when summary.json's largest rate of the surface, or its place, is not the map's."""
    if wear is None or peak is None:
        return
    value, i, j = peak
    keys = {"piston": ("piston_rate_max_m_per_h", "piston_max_theta_deg", "piston_max_z_m", 1.0, "z"),
            "liner": ("liner_rate_max_m_per_h", "liner_max_theta_deg", "liner_max_depth_m", -1.0, "depth")}
    k_rate, k_theta, k_pos, sign, where = keys[m["surface"]]
    try:
        s_rate, s_theta, s_pos = float(wear[k_rate]), float(wear[k_theta]), float(wear[k_pos])
    except (KeyError, TypeError, ValueError):
        return
    pos = sign * m["z"][i]
    if abs(s_rate - value) > 1e-6 * abs(value) or angle_apart(s_theta, m["theta"][j]) > 1e-4 or abs(s_pos - pos) > 1e-9:
        print(f"plot_wear.py: warning: '{m['path']}': the map's largest rate {value:.6g} m/h at θ "
              f"{m['theta'][j]:.4g}°, {where} {pos:.6g} m is not summary.json's "
              f"{s_rate:.6g} m/h at {s_theta:.4g}°, {where} {s_pos:.6g} m", file=sys.stderr)


def draw(fig, ax, m, peak, void_note, decades=None):
    surface = m["surface"]
    rate = np.ma.masked_array(np.where(m["blank"], 0.0, m["rate"]) * 1e9, mask=m["blank"])  # nm/h
    if surface == "piston":
        y = m["z"] * 1e3
        ylabel = "z (mm), piston frame:\npin axis 0, + towards the crown"
        title = "Skirt (piston frame)"
    else:
        y = -m["z"] * 1e3
        ylabel = "depth below the deck (mm),\nliner frame"
        title = "Liner (liner frame)"
    theta = m["theta"]
    rows, cols = np.argsort(y, kind="stable"), np.argsort(theta, kind="stable")
    vmax = float(rate.max()) if rate.count() else 0.0
    label = "mean wear rate (nm/h)"
    if decades and vmax > 0.0:
        norm = matplotlib.colors.LogNorm(vmin=vmax * 10.0 ** -decades, vmax=vmax, clip=True)
        rate = np.ma.masked_array(np.maximum(rate.filled(0.0), norm.vmin), mask=rate.mask)
        label = f"mean wear rate (nm/h), log scale\nlowest colour: ≤ {norm.vmin:.2g} nm/h (and 0)"
    else:
        norm = matplotlib.colors.Normalize(vmin=0.0, vmax=vmax if vmax > 0.0 else 1.0)
    mesh = ax.pcolormesh(theta[cols], y[rows], rate[np.ix_(rows, cols)], cmap="viridis", shading="nearest",
                         norm=norm)
    fig.colorbar(mesh, ax=ax, label=label, pad=0.02)
    ax.set_facecolor("0.85")  # grey: no skirt (blank)
    if m["periodic"]:
        ax.set_xlim(theta.min(), theta.max())  # node 0 half at each end: the seam
        ax.set_xticks(np.arange(np.ceil(theta.min() / 45.0) * 45.0, theta.max() + 1e-9, 45.0))
    for x in (0.0, 180.0, 360.0, -180.0):
        if theta.min() < x < theta.max():
            ax.axvline(x, color="w", lw=0.6, ls=":")
    ax.set_ylim(y.min() - 0.5 * abs(y[rows][1] - y[rows][0]) if len(y) > 1 else y.min() - 0.5,
                y.max() + 0.5 * abs(y[rows][-1] - y[rows][-2]) if len(y) > 1 else y.max() + 0.5)
    if surface == "liner":
        ax.invert_yaxis()  # depth increasing downwards
    ax.set_xlabel("θ (deg): 0 major thrust, 180 minor thrust side")
    ax.set_ylabel(ylabel)
    ax.set_title(f"{title}: mean Archard wear rate over the last cycle", fontsize=10)
    if peak is None:
        ax.text(0.5, 0.5, "no wear on this surface\n(wear coefficient 0 or no contact)", transform=ax.transAxes,
                ha="center", va="center", fontsize=9, bbox=dict(boxstyle="round", fc="w", ec="0.5"))
        return
    value, i, j = peak
    tx, ty = theta[j], y[i]
    ax.plot([tx], [ty], marker="o", ms=11, mfc="none", mec="tab:red", mew=1.6, ls="none", zorder=5)
    place = f"z = {ty:.2f} mm" if surface == "piston" else f"depth {ty:.2f} mm"
    # Text towards the middle of the panel from the marker.
    fx, fy = ax.transLimits.transform((tx, ty))
    ax.annotate(f"max {value * 1e9:.3g} nm/h\nθ = {tx:.1f}°, {place}", (tx, ty),
                xytext=(-40 if fx > 0.5 else 40, -30 if fy > 0.5 else 30), textcoords="offset points",
                ha="right" if fx > 0.5 else "left", va="top" if fy > 0.5 else "bottom", fontsize=8,
                bbox=dict(boxstyle="round", fc="w", ec="0.4", alpha=0.9),
                arrowprops=dict(arrowstyle="->", color="0.2", lw=0.8), zorder=6)
    if void_note:
        ax.text(0.01, 0.01, void_note, transform=ax.transAxes, fontsize=6.5, color="0.25", va="bottom",
                bbox=dict(boxstyle="square,pad=0.2", fc="w", ec="none", alpha=0.7))


def wear_files(directory):
    """The (surface, file name) of the wear maps RESULTS_DIR holds; Note when none."""
    if not os.path.isdir(directory):
        raise PlotError(f"'{directory}' is not a directory (expected a flexehd results directory)")
    present = [(s, n) for s, n in FILES if os.path.isfile(os.path.join(directory, n))]
    if not present:
        raise Note(f"'{directory}' has no wear maps (wear_piston.vts, wear_liner.vts: the case turns wear on "
                   f"with contact.piston_wear_coefficient or liner_wear_coefficient > 0): no wear_maps.png")
    return present


def plot_wear(directory, present, out_dir, decades=None):
    for s, n in FILES:
        if (s, n) not in present:
            print(f"plot_wear.py: note: '{directory}' has no {n}: plotting the other map alone", file=sys.stderr)
    maps = [read_map(directory, s, n) for s, n in present]
    wear, name = summary_wear(directory)

    piston = next((m for m in maps if m["surface"] == "piston"), None)
    mask, why = void_mask(directory, piston["xyz"]) if piston is not None else (None, "no skirt map")
    notes = {}
    if mask is not None:
        void_columns = mask.all(axis=0)
        for m in maps:
            if m["surface"] == "piston":
                m["blank"] |= mask
                notes["piston"] = "grey: no skirt (node_kind 2 of film.pvd)"
            elif m["rate"].shape[1] == mask.shape[1]:
                m["blank"] |= void_columns[None, :]
                notes["liner"] = "grey: θ columns without skirt (node_kind 2 of film.pvd)"
    else:
        note = f"void nodes not marked ({why}): 0 = no contact or no skirt"
        notes = {"piston": note, "liner": note}
        print(f"plot_wear.py: note: {note}", file=sys.stderr)

    fig, axes = plt.subplots(1, len(maps), figsize=(6.6 * len(maps), 5.6), squeeze=False)
    for ax, m in zip(axes[0], maps):
        peak = maximum(m)
        cross_check(m, peak, wear)
        if peak is not None:
            value, i, j = peak
            where = f"z {m['z'][i] * 1e3:.3f} mm" if m["surface"] == "piston" else f"depth {-m['z'][i] * 1e3:.3f} mm"
            print(f"{m['surface']}: max {value * 1e9:.6g} nm/h at θ {m['theta'][j]:.2f} deg, {where}")
        else:
            print(f"{m['surface']}: no wear")
        draw(fig, ax, m, peak, notes.get(m["surface"]), decades)
    if name:
        fig.suptitle(name, fontsize=9, color="0.3")
    fig.tight_layout()
    save(fig, out_dir, "wear_maps.png")


def main(argv=None):
    parser = argparse.ArgumentParser(
        description="Plot the Archard wear maps (wear_piston.vts, wear_liner.vts) of a flexehd results "
                    "directory as wear_maps.png.")
    parser.add_argument("results", metavar="RESULTS_DIR", help="results directory of a run with wear turned on")
    parser.add_argument("--out", metavar="DIR", help="directory for the PNG (default: RESULTS_DIR/plots_wear)")
    parser.add_argument("--log", metavar="DECADES", type=float,
                        help="logarithmic colour scale over DECADES below each map's largest rate (default: "
                             "linear from 0); the rates span many decades, mostly near the maxima")
    args = parser.parse_args(argv)
    if args.log is not None and not args.log > 0.0:
        parser.error("--log needs a positive number of decades")
    try:
        present = wear_files(args.results)
        vtk_modules()  # both notes (no wear files, no VTK) before the output directory is made
        out_dir = args.out or os.path.join(args.results, "plots_wear")
        try:
            os.makedirs(out_dir, exist_ok=True)
        except OSError as e:
            raise PlotError(f"cannot create the output directory '{out_dir}': {e.strerror}") from None
        plot_wear(args.results, present, out_dir, args.log)
    except Note as e:
        print(f"plot_wear.py: note: {e}", file=sys.stderr)
        return 0
    except (PlotError, OSError) as e:
        print(f"plot_wear.py: error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
