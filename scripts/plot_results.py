#!/usr/bin/python3
"""Plots the history of a flexehd run (history.csv in a results directory) as PNG figures.

    /usr/bin/python3 scripts/plot_results.py RESULTS_DIR [--compare OTHER_DIR ...]
                                             [--labels HD EHD ...] [--cycle N] [--out DIR]

Uses the last complete engine cycle of each run (the `cycle` column; --cycle picks another)
and writes, into --out (default RESULTS_DIR/plots):

  secondary_motion.png  lateral displacement (um) with the clearance band, tilt (deg) and side
                        force (kN) with the cylinder pressure over the crank angle, runs overlaid
                        (HD vs EHD, like Fig. 5 of Dlugos et al. 2016)
  friction.png          friction force on the liner (N, hydrodynamic and boundary) and the
                        dissipated power (W), with cycle averages
  contact.png           asperity contact force (N) and boundary friction on the liner (N)
  film.png              minimum film thickness (um) and maximum film pressure (MPa)
  film_maps.png         film pressure (max over the skirt's height) and film thickness (min over
                        it) as maps over the circumferential angle and the crank angle, from the
                        VTK snapshots of RESULTS_DIR (film.pvd); skipped without snapshots

Needs numpy, matplotlib and, for film_maps.png, VTK's Python modules (Debian: python3-numpy,
python3-matplotlib, python3-vtk9). Column names, units and sign conventions:
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

REQUIRED = ["cycle", "crank_deg", "time_s", "lateral_m", "tilt_rad", "side_force_n", "contact_force_n",
            "liner_friction_hydrodynamic_n", "liner_friction_boundary_n", "dissipated_power_w",
            "boundary_friction_power_w", "cylinder_pressure_pa", "min_film_m", "max_pressure_pa"]
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


def smallest_clearance(directory):
    """The smallest centred clearance at mid-stroke (m) of summary.json, or None."""
    try:
        with open(os.path.join(directory, "summary.json")) as f:
            return float(json.load(f)["centred_clearance_m"]["mid_stroke"]["min"])
    except (OSError, ValueError, KeyError, TypeError):
        return None


def plot_secondary_motion(runs, out_dir):
    fig, axes = plt.subplots(3, 1, sharex=True, figsize=(9, 8.5),
                             gridspec_kw={"height_ratios": [1.2, 1.2, 0.9]})
    band = False
    for k, (label, sel, _, directory) in enumerate(runs):
        style = dict(color=COLORS[k % len(COLORS)], ls=STYLES[k % len(STYLES)], lw=1.3)
        axes[0].plot(sel["crank_deg"], sel["lateral_m"] * 1e6, label=label, **style)
        axes[1].plot(sel["crank_deg"], np.degrees(sel["tilt_rad"]), label=label, **style)
        axes[2].plot(sel["crank_deg"], sel["side_force_n"] * 1e-3, label=label, **style)
        c = smallest_clearance(directory)
        if c is not None:
            band = True
            for sign in (-1, 1):
                axes[0].axhline(sign * c * 1e6, color=style["color"], lw=0.8, ls=(0, (6, 3)), alpha=0.7,
                                label=f"{label}: ±{c * 1e6:.1f} µm clearance" if sign > 0 else None)
    axes[0].set_ylabel("lateral displacement (µm)\n+ = major thrust side")
    if band:
        axes[0].text(0.01, 0.02, "dashed: smallest centred clearance at mid-stroke (rigid skirt). With EHD the "
                     "skirt deforms,\nso the pin axis can move beyond it.", transform=axes[0].transAxes,
                     fontsize=7, color="0.3", va="bottom")
    axes[1].set_ylabel("tilt (deg)\n+ = top towards thrust side")
    axes[2].set_ylabel("side force (kN)")
    gas = axes[2].twinx()
    _, first, _, _ = runs[0]
    gas.plot(first["crank_deg"], first["cylinder_pressure_pa"] * 1e-6, color="0.55", lw=0.9, ls="-",
             label=f"cylinder pressure ({runs[0][0]}, absolute)")
    gas.set_ylabel("cylinder pressure (MPa)", color="0.45")
    gas.tick_params(axis="y", colors="0.45")
    gas.legend(loc="lower right", fontsize=7)
    axes[0].set_title("Piston secondary motion" + cycle_note(runs), pad=14)
    for ax in axes:
        ax.legend(loc="upper right" if ax is axes[2] else "best", fontsize=7)
    decorate_crank_axis(axes)
    fig.tight_layout()
    save(fig, out_dir, "secondary_motion.png")


def plot_friction(runs, out_dir):
    fig, axes = plt.subplots(2, 1, sharex=True, figsize=(9, 6.5))
    for k, (label, sel, _, _) in enumerate(runs):
        color = COLORS[k % len(COLORS)]
        axes[0].plot(sel["crank_deg"], sel["liner_friction_hydrodynamic_n"], color=color, lw=1.3,
                     ls=STYLES[k % len(STYLES)], label=f"{label}: film shear")
        if np.any(sel["liner_friction_boundary_n"] != 0.0):
            axes[0].plot(sel["crank_deg"], sel["liner_friction_boundary_n"], color=color, lw=0.9, ls=":",
                         label=f"{label}: boundary friction")
        mean_power = cycle_mean(sel, "dissipated_power_w")
        mean_boundary = cycle_mean(sel, "boundary_friction_power_w")
        axes[1].plot(sel["crank_deg"], sel["dissipated_power_w"], color=color, lw=1.3, ls=STYLES[k % len(STYLES)],
                     label=f"{label} (cycle mean {mean_power:.2f} W, boundary {mean_boundary:.2f} W)")
        axes[1].axhline(mean_power, color=color, lw=0.8, ls=":")
    axes[0].set_ylabel("friction force on the liner (N)\n+ = towards the head")
    axes[1].set_ylabel("dissipated power (W)\nviscous + boundary, ≥ 0")
    axes[1].set_ylim(bottom=0)
    axes[0].set_title("Skirt friction" + cycle_note(runs), pad=14)
    for ax in axes:
        ax.legend(loc="best", fontsize=8)
    decorate_crank_axis(axes)
    fig.tight_layout()
    save(fig, out_dir, "friction.png")


def plot_columns(runs, out_dir, name, title, panels, height=6.5):
    """One panel per (column, scale, y label) over the crank angle, runs overlaid."""
    fig, axes = plt.subplots(len(panels), 1, sharex=True, figsize=(9, height))
    for k, (label, sel, _, _) in enumerate(runs):
        style = dict(color=COLORS[k % len(COLORS)], ls=STYLES[k % len(STYLES)], lw=1.3)
        for ax, (column, scale, _) in zip(axes, panels):
            ax.plot(sel["crank_deg"], sel[column] * scale, label=label, **style)
    for ax, (_, _, ylabel) in zip(axes, panels):
        ax.set_ylabel(ylabel)
        ax.legend(loc="best", fontsize=8)
    axes[0].set_title(title + cycle_note(runs), pad=14)
    decorate_crank_axis(axes)
    fig.tight_layout()
    save(fig, out_dir, name)


def plot_contact(runs, out_dir):
    plot_columns(runs, out_dir, "contact.png", "Skirt–liner asperity contact",
                 [("contact_force_n", 1.0, "lateral contact force\non the piston (N)"),
                  ("liner_friction_boundary_n", 1.0, "boundary friction\non the liner (N)")], height=6.0)


def read_film_snapshots(directory):
    """The film snapshots of film.pvd: crank angles (deg), theta of the columns (deg) and, per
    snapshot, the largest pressure (Pa) and the smallest film thickness (m) over each column's
    skirt nodes (NaN where a column has none). None when the directory has no film.pvd."""
    pvd = os.path.join(directory, "film.pvd")
    if not os.path.isfile(pvd):
        return None
    try:
        from vtkmodules.vtkIOXML import vtkXMLStructuredGridReader
        from vtkmodules.util.numpy_support import vtk_to_numpy
    except ImportError:
        raise PlotError("film_maps.png needs VTK's Python modules (Debian python3-vtk9: "
                        "bash scripts/install_deps.sh --with-python)") from None
    with open(pvd) as f:
        files = re.findall(r'file="([^"]+)"', f.read())
    if not files:
        return None
    crank, p_max, h_min, theta = [], [], [], None
    for name in files:
        path = os.path.join(directory, name)
        reader = vtkXMLStructuredGridReader()
        reader.SetFileName(path)
        reader.Update()
        grid = reader.GetOutput()
        dims = grid.GetDimensions()
        fd, pd = grid.GetFieldData(), grid.GetPointData()
        if fd.GetArray("crank_deg") is None or pd.GetArray("pressure_pa") is None:
            raise PlotError(f"'{path}' lacks the field data 'crank_deg' or the array 'pressure_pa'")
        shape = (dims[1], dims[0])  # axial rows, theta columns
        p = vtk_to_numpy(pd.GetArray("pressure_pa")).reshape(shape)
        h = vtk_to_numpy(pd.GetArray("film_thickness_m")).reshape(shape)
        kind = vtk_to_numpy(pd.GetArray("node_kind")).reshape(shape)
        xyz = vtk_to_numpy(grid.GetPoints().GetData()).reshape(shape + (3,))
        if theta is None:  # -90 ... 270 deg: the thrust (0) and antithrust (180) sides each in one piece
            theta = (np.degrees(np.arctan2(xyz[0, :, 1], xyz[0, :, 0])) + 90.0) % 360.0 - 90.0
        skirt = kind != 2
        with np.errstate(invalid="ignore"):
            p_max.append(np.where(skirt.any(axis=0), np.where(skirt, p, -np.inf).max(axis=0), np.nan))
            h_min.append(np.where(skirt.any(axis=0), np.where(skirt, h, np.inf).min(axis=0), np.nan))
        crank.append(fd.GetArray("crank_deg").GetValue(0))
    order = np.argsort(crank, kind="stable")
    return np.asarray(crank)[order], theta, np.asarray(p_max)[order], np.asarray(h_min)[order]


def plot_film_maps(label, directory, out_dir):
    snaps = read_film_snapshots(directory)
    if snaps is None:
        print(f"plot_results.py: note: '{directory}' has no film snapshots (output.vtk_every_deg: 0): "
              f"no film_maps.png", file=sys.stderr)
        return
    crank, theta, p_max, h_min = snaps
    if len(crank) < 2:
        print(f"plot_results.py: note: '{directory}' has only {len(crank)} film snapshot: no film_maps.png",
              file=sys.stderr)
        return
    order = np.argsort(theta, kind="stable")  # the seam column (θ repeated) drops out below
    theta, p_max, h_min = theta[order], p_max[:, order], h_min[:, order]
    keep = np.concatenate(([True], np.diff(theta) > 1e-9))
    theta, p_max, h_min = theta[keep], p_max[:, keep], h_min[:, keep]
    fig, axes = plt.subplots(2, 1, sharex=True, figsize=(9, 7.0))
    p = np.ma.masked_invalid(p_max * 1e-6)  # masked: no skirt in that column
    m0 = axes[0].pcolormesh(crank, theta, p.T, cmap="viridis", shading="nearest")
    fig.colorbar(m0, ax=axes[0], label="film pressure, max over z (MPa, gauge)")
    h = np.ma.masked_invalid(h_min * 1e6)
    m1 = axes[1].pcolormesh(crank, theta, h.T, cmap="magma", vmin=min(0.0, float(h.min())), shading="nearest")
    fig.colorbar(m1, ax=axes[1], label="film thickness, min over z (µm)")
    for ax in axes:
        ax.set_ylabel("θ (deg): 0 major thrust,\n180 minor thrust side")
        ax.set_yticks(np.arange(-90, 271, 45))
        ax.set_facecolor("0.85")  # grey: no skirt
        ax.set_xlim(0, 720)
        ax.set_xticks(np.arange(0, 721, 90))
        for x in (180, 360, 540):
            ax.axvline(x, color="w", lw=0.6, ls=":")
    axes[1].set_xlabel("crank angle (deg)")
    axes[0].set_title(f"Skirt film over the cycle: {label} ({len(crank)} snapshots, output.vtk_every_deg)", pad=10)
    fig.tight_layout()
    save(fig, out_dir, f"film_maps_{safe_name(label)}.png")


def safe_name(label):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", label) or "run"


def plot_film(runs, out_dir):
    plot_columns(runs, out_dir, "film.png", "Oil film",
                 [("min_film_m", 1e6, "minimum film thickness (µm)\n< 0: the surfaces overlap"),
                  ("max_pressure_pa", 1e-6, "maximum film pressure (MPa, gauge)")])


def plot_oil(runs, out_dir):
    """The mass-conserving film's oil (only the runs that have the oil columns)."""
    oily = [r for r in runs if "film_oil_m3" in r[1]]
    if not oily:
        return
    # The oil columns sum over the contacts on the layer (the skirt, and an oil-control ring).
    plot_columns(oily, out_dir, "oil.png", "Oil on the skirt and the liner (mass-conserving film)",
                 [("wetted_share", 100.0, "skirt area in\nfull film (%)"),
                  ("film_oil_m3", 1e9, "oil in the\nfilms (mm³)"),
                  ("liner_oil_m3", 1e9, "oil on the liner\noutside the covers (mm³)"),
                  ("oil_in_m3_per_s", 1e9, "oil into the films\nat their edges (mm³/s)")], height=8.5)


def ring_names(sel):
    """The rings of a run, from its ring_<name>_min_film_m columns, in column order."""
    return [c[len("ring_"):-len("_min_film_m")] for c in sel
            if c.startswith("ring_") and c.endswith("_min_film_m")]


def plot_rings(runs, out_dir):
    """Per run with a ring pack: the friction power of the skirt and of each ring, and each
    ring's minimum film, over the crank angle."""
    for label, sel, cycle, _ in runs:
        rings = ring_names(sel)
        if not rings:
            continue
        fig, axes = plt.subplots(2, 1, sharex=True, figsize=(9, 6.5))
        skirt = cycle_mean(sel, "dissipated_power_w")
        axes[0].plot(sel["crank_deg"], sel["dissipated_power_w"], color=COLORS[0], lw=1.3,
                     label=f"skirt (cycle mean {skirt:.2f} W)")
        for k, ring in enumerate(rings, start=1):
            color = COLORS[k % len(COLORS)]
            column = f"ring_{ring}_friction_power_w"
            axes[0].plot(sel["crank_deg"], sel[column], color=color, lw=1.1,
                         label=f"{ring} (cycle mean {cycle_mean(sel, column):.2f} W)")
            axes[1].plot(sel["crank_deg"], sel[f"ring_{ring}_min_film_m"] * 1e6, color=color, lw=1.1, label=ring)
        finish_ring_panels(fig, axes, ("friction power (W)\ntaken from the piston",
                                       "ring minimum gap (µm)\n< 0: asperities overlap"),
                           f"Piston rings and skirt: {label}" + cycle_note([(label, sel, cycle, None)]),
                           out_dir, f"rings_{safe_name(label)}.png")


def finish_ring_panels(fig, axes, ylabels, title, out_dir, name):
    """The two crank-angle panels of a ring plot: the zero line below, labels, legends, saved."""
    axes[1].axhline(0.0, color="0.5", lw=0.6)
    for ax, ylabel in zip(axes, ylabels):
        ax.set_ylabel(ylabel)
        ax.legend(loc="best", fontsize=8)
    axes[0].set_title(title, pad=14)
    decorate_crank_axis(axes)
    fig.tight_layout()
    save(fig, out_dir, name)


def plot_ring_gas(runs, out_dir):
    """Per run with the lands' gas (ring_gas): the cylinder pressure and the pressure below each
    ring over the crank angle, the gas past each ring (the last ring's: blow-by) and, with ring
    lift, each ring's height above its groove's lower flank and, where a ring collapsed radially,
    how far its face left the liner."""
    for label, sel, cycle, _ in runs:
        rings = [r for r in ring_names(sel) if f"ring_{r}_gas_below_pa" in sel]
        if not rings:
            continue
        lift = all(f"ring_{r}_axial_position_m" in sel for r in rings)
        collapsed = [r for r in rings if f"ring_{r}_face_opening_m" in sel and sel[f"ring_{r}_face_opening_m"].max() > 0]
        panels = 2 + lift + bool(collapsed)
        fig, axes = plt.subplots(panels, 1, sharex=True, figsize=(9, 2.2 + 2.25 * panels))
        if lift:
            for k, ring in enumerate(rings, start=1):
                axes[2].plot(sel["crank_deg"], sel[f"ring_{ring}_axial_position_m"] * 1e6,
                             color=COLORS[k % len(COLORS)], lw=1.1, label=ring)
        for k, ring in enumerate(rings, start=1):
            if ring in collapsed:
                axes[3].plot(sel["crank_deg"], sel[f"ring_{ring}_face_opening_m"] * 1e6,
                             color=COLORS[k % len(COLORS)], lw=1.1, label=ring)
        axes[0].plot(sel["crank_deg"], sel["cylinder_pressure_pa"] * 1e-5, color=COLORS[0], lw=1.3, label="cylinder")
        for k, ring in enumerate(rings, start=1):
            color = COLORS[k % len(COLORS)]
            if k < len(rings):  # the last ring's "below" is the crankcase
                axes[0].plot(sel["crank_deg"], sel[f"ring_{ring}_gas_below_pa"] * 1e-5, color=color, lw=1.1,
                             label=f"land below {ring}")
            column = f"ring_{ring}_gas_flow_l_per_min"
            axes[1].plot(sel["crank_deg"], sel[column], color=color, lw=1.1,
                         label=f"past {ring} (cycle mean {cycle_mean(sel, column):.3g} l/min)")
        finish_ring_panels(fig, axes, ("absolute pressure (bar)",
                                       "gas past the ring\n(l/min at 0 °C, 1 atm; > 0 down)",
                                       "height above the\ngroove's lower flank (µm)",
                                       "face off the liner\n(radial collapse, µm)"),
                           f"Gas between the rings: {label}" + cycle_note([(label, sel, cycle, None)]),
                           out_dir, f"ring_gas_{safe_name(label)}.png")


def cycle_note(runs):
    cycles = {f"{c}{note}" for _, _, (c, note), _ in runs}
    return f", cycle {cycles.pop()}" if len(cycles) == 1 else ", cycles " + ", ".join(
        f"{label}: {c}{note}" for label, _, (c, note), _ in runs)


def main(argv=None):
    parser = argparse.ArgumentParser(
        description="Plot history.csv of flexehd results directories as PNG figures "
                    "(secondary motion, friction, film, oil, the ring pack and its gas).")
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
            runs.append((label, sel, (c, note), d))
        out_dir = args.out or os.path.join(args.results, "plots")
        try:
            os.makedirs(out_dir, exist_ok=True)
        except OSError as e:
            raise PlotError(f"cannot create the output directory '{out_dir}': {e.strerror}") from None
        plot_secondary_motion(runs, out_dir)
        plot_friction(runs, out_dir)
        plot_contact(runs, out_dir)
        plot_film(runs, out_dir)
        plot_oil(runs, out_dir)
        plot_rings(runs, out_dir)
        plot_ring_gas(runs, out_dir)
        for label, _, _, d in runs:
            plot_film_maps(label, d, out_dir)
    except (PlotError, OSError) as e:
        print(f"plot_results.py: error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
