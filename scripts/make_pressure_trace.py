#!/usr/bin/python3
"""Cylinder pressure trace of the example engine (examples/engine86/cylinder_pressure.csv).

Model (documented in docs/case-file.md, "The pressure trace"): a single-zone cycle of a
4-stroke SI engine, bore 86 mm, stroke 86 mm, rod 143.5 mm, compression ratio 10, at
1000 rpm and part load (intake manifold 0.7 bar absolute):

  * intake stroke 0-180 deg at the manifold pressure, after a 20 deg cosine blend from the
    exhaust back-pressure at gas-exchange TDC (valve overlap);
  * compression 180-360 deg and expansion 360-540 deg from the first law for a closed
    system with a polytropic exponent n = 1.3 standing in for the ratio of specific heats
    and the wall heat loss (the single-zone heat-release equation of Heywood 1988, ch. 9,
    with gamma -> n):
        dp/dtheta = (n - 1)/V * dQ/dtheta - n p/V * dV/dtheta
  * heat release: Wiebe function (Wiebe 1970; Heywood 1988, ch. 9)
        x_b = 1 - exp(-a ((theta - theta_0)/dtheta)^(m + 1)),  a = 5, m = 2,
    start of combustion 338 deg (22 deg before firing TDC), duration 50 deg, apparent
    (net) heat release Q = eta * m_fuel * LHV with eta = 0.75 (combustion efficiency times
    the fraction not lost to the walls, which the polytropic exponent only partly covers);
    trapped mass from p, V at BDC and 320 K, stoichiometric gasoline-air (AFR 14.7,
    LHV 44 MJ/kg);
  * blowdown: cosine blend from the expansion pressure to the exhaust back-pressure
    1.05 bar between exhaust valve opening at 500 deg (40 deg before BDC) and 560 deg;
    exhaust stroke at 1.05 bar.

Integrated with classical RK4 at 0.05 deg, written at 0.5 deg from 0 to 720 deg inclusive
(the 720 deg row repeats the 0 deg row: the trace is periodic). Run with
/usr/bin/python3 (numpy only); it prints the peak pressure, its angle and the IMEP.
"""

import argparse
import math
import os
import sys

import numpy as np

# --- engine geometry (examples/engine86/case.yaml) -------------------------------------
BORE = 0.086            # m
STROKE = 0.086          # m
ROD = 0.1435            # m
CR = 10.0               # compression ratio
AREA = math.pi * BORE**2 / 4
V_D = AREA * STROKE     # displacement, m^3
V_C = V_D / (CR - 1.0)  # clearance volume, m^3

# --- operating point and model parameters ----------------------------------------------
P_INTAKE = 0.70e5       # Pa, intake manifold (part load)
P_EXHAUST = 1.05e5      # Pa, exhaust back-pressure
T_INTAKE = 320.0        # K, charge temperature at BDC
R_AIR = 287.0           # J/(kg K)
AFR = 14.7              # stoichiometric gasoline
LHV = 44.0e6            # J/kg
ETA = 0.75              # apparent (net) heat-release fraction of the fuel energy
N_POLY = 1.3            # polytropic exponent
WIEBE_A, WIEBE_M = 5.0, 2.0
THETA_SOC = 338.0       # deg, start of combustion
THETA_DUR = 50.0        # deg, combustion duration
THETA_EVO = 500.0       # deg, exhaust valve opening
THETA_BLOW = 60.0       # deg, blowdown duration
THETA_OVERLAP = 20.0    # deg, exhaust -> intake pressure blend after gas-exchange TDC


def volume(theta_deg):
    """Cylinder volume at crank angle theta (0 and 360 deg = TDC)."""
    th = np.radians(theta_deg)
    r = STROKE / 2
    s = r + ROD - (r * np.cos(th) + np.sqrt(ROD**2 - (r * np.sin(th)) ** 2))
    return V_C + AREA * s


def dvolume(theta_deg):
    """dV/dtheta per degree."""
    th = np.radians(theta_deg)
    r = STROKE / 2
    ds = r * np.sin(th) * (1 + r * np.cos(th) / np.sqrt(ROD**2 - (r * np.sin(th)) ** 2))
    return AREA * ds * math.pi / 180.0


def heat_release_total():
    mass = P_INTAKE * volume(180.0) / (R_AIR * T_INTAKE)  # trapped mixture, kg
    fuel = mass / (1.0 + AFR)
    return ETA * fuel * LHV


def dq(theta_deg, q_total):
    """dQ/dtheta per degree (Wiebe)."""
    x = (theta_deg - THETA_SOC) / THETA_DUR
    if x <= 0.0 or x >= 1.0:
        return 0.0
    m1 = WIEBE_M + 1.0
    return q_total * WIEBE_A * m1 / THETA_DUR * x**WIEBE_M * math.exp(-WIEBE_A * x**m1)


def closed_cycle(step=0.05):
    """p(theta) for 180..540 deg by RK4 on the first law."""
    q_total = heat_release_total()

    def f(th, p):
        v = volume(th)
        return (N_POLY - 1.0) / v * dq(th, q_total) - N_POLY * p / v * dvolume(th)

    n = int(round((540.0 - 180.0) / step))
    th = np.linspace(180.0, 540.0, n + 1)
    p = np.empty_like(th)
    p[0] = P_INTAKE
    for i in range(n):
        t, y = th[i], p[i]
        k1 = f(t, y)
        k2 = f(t + step / 2, y + step / 2 * k1)
        k3 = f(t + step / 2, y + step / 2 * k2)
        k4 = f(t + step, y + step * k3)
        p[i + 1] = y + step / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return th, p, q_total


def blend(t):
    """1 at t = 0 to 0 at t = 1, zero slope at both ends."""
    return 0.5 * (1.0 + math.cos(math.pi * t))


def trace(resolution=0.5):
    th_c, p_c, q_total = closed_cycle()
    angles = np.arange(0.0, 720.0 + resolution / 2, resolution)
    p = np.empty_like(angles)
    for i, a in enumerate(angles):
        if a < THETA_OVERLAP:
            p[i] = P_INTAKE + (P_EXHAUST - P_INTAKE) * blend(a / THETA_OVERLAP)
        elif a <= 180.0:
            p[i] = P_INTAKE
        elif a <= THETA_EVO:
            p[i] = np.interp(a, th_c, p_c)
        elif a < THETA_EVO + THETA_BLOW:
            w = blend((a - THETA_EVO) / THETA_BLOW)
            p[i] = w * np.interp(a, th_c, p_c) + (1.0 - w) * P_EXHAUST
        else:
            p[i] = P_EXHAUST
    return angles, p, q_total


def imep(angles, p):
    """Indicated mean effective pressure over the 720 deg cycle (trapezoidal p dV)."""
    v = volume(angles)
    return float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(v)) / V_D)


def main():
    global P_INTAKE, ETA
    here = os.path.dirname(os.path.abspath(__file__))
    default_out = os.path.join(here, "..", "examples", "engine86", "cylinder_pressure.csv")
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=os.path.normpath(default_out))
    ap.add_argument("--resolution", type=float, default=0.5, help="deg between rows")
    ap.add_argument("--intake-pressure", type=float, default=P_INTAKE,
                    help="Pa, absolute intake manifold pressure (default 0.7e5: part load; 1.0e5: full load)")
    ap.add_argument("--motored", action="store_true", help="no combustion (compression and expansion only)")
    args = ap.parse_args()
    if not (1e4 <= args.intake_pressure <= 5e5):
        ap.error("--intake-pressure: expected an absolute pressure between 1e4 and 5e5 Pa, got %g"
                 % args.intake_pressure)
    P_INTAKE = args.intake_pressure
    if args.motored:
        ETA = 0.0
    load = "motored" if args.motored else ("part load" if P_INTAKE < 0.95e5 else "full load")

    angles, p, q_total = trace(args.resolution)
    k = int(np.argmax(p))
    mep = imep(angles, p)
    with open(args.out, "w") as out:
        out.write("# Cylinder pressure of the flexehd example engine (bore 86 mm, stroke 86 mm,\n")
        out.write("# compression ratio 10, 1000 rpm, %s), generated by scripts/make_pressure_trace.py:\n" % load)
        out.write("# single-zone first law, polytropic n = %.2f, Wiebe a = %g, m = %g, start %g deg,\n"
                  % (N_POLY, WIEBE_A, WIEBE_M, THETA_SOC))
        out.write("# duration %g deg, net heat release %.0f J, intake %.2f bar, exhaust %.2f bar.\n"
                  % (THETA_DUR, q_total, P_INTAKE / 1e5, P_EXHAUST / 1e5))
        out.write("# Peak %.3f MPa at %.1f deg, IMEP %.3f MPa. Model and sources: docs/case-file.md.\n"
                  % (p[k] / 1e6, angles[k], mep / 1e6))
        out.write("# 0 deg = gas-exchange TDC, 360 deg = firing TDC; pressure absolute.\n")
        out.write("crank_angle_deg,pressure_pa\n")
        for a, v in zip(angles, p):
            out.write("%g,%.1f\n" % (a, v))
    print("wrote %s: %d rows, peak %.3f MPa at %.1f deg, IMEP %.3f MPa, heat release %.0f J"
          % (args.out, len(angles), p[k] / 1e6, angles[k], mep / 1e6, q_total))
    return 0


if __name__ == "__main__":
    sys.exit(main())
