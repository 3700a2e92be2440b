#!/usr/bin/python3
"""Writes the superfluid fountain case files (paper 3 sec. III.C) at a given resolution: the
geometry the issue gives, in mm with y up and the capillary on x = 0, placed for dr = d / N
(the bodies sit at x = xi - (17.1 + r_cap + dr / 2)). The committed cases were written by

    /usr/bin/python3 tools/plots/superfluid_fountain_case.py 4 fountain-coarse 80
    /usr/bin/python3 tools/plots/superfluid_fountain_case.py 2 fountain-small 80 --reversible

Usage: superfluid_fountain_case.py N NAME POWER [--reversible] [--support S] [--out DIR]
  N             particles across the capillary's width d = 1.55 mm (the paper: 40)
  NAME          case name (writes DIR/NAME.toml, DIR default models/superfluid/cases)
  POWER         heater power W (W/m)
  --reversible  no viscosity, conduction, superleak or heater, 2000 steps: the reversible core on
                the fountain's geometry (the acceptance's bitwise check)
  --support S   the kernel's support radius in dr (default 2.8: Table I's h as the authors'
                fountain_2d.jl uses it, "h = 2.8*dr # size of kernel support"; 5.6 is eq. 17 as
                printed, support 2h). dt = h / (5 u1) with h = 2.8 dr either way (Table I); the
                glass and the cryostat's walls are ceil(S) layers thick
"""

import argparse
import math
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
MM = 1e-3
D = 1.55 * MM
# The L of the issue, (0, 0), (0, 23.7), (17.1, 23.7), (17.1, 16.7), (9.9, 16.7), (9.9, 0), with
# the disc of radius 4.95 centred at (4.95, 0) that rounds the column's bottom: the column is
# carried down to y = -4.95 and its two bottom corners rounded with radius 4.95, whose arcs are
# centred at (4.95, 0) and meet at (4.95, -4.95): the L and the disc's union.
BODY = [(0, -4.95), (0, 23.7), (17.1, 23.7), (17.1, 16.7), (9.9, 16.7), (9.9, -4.95)]
RADII = [4.95, 10.7, 0, 2, 2, 4.95]
CAPILLARY_WALL = [(15.6, 23.7), (15.6, 33.7), (17.1, 33.7), (17.1, 23.7)]


def fmt(value):
    return repr(round(value, 12))


def points(vertices):
    return ", ".join(f"{fmt(x * MM)}, {fmt(y * MM)}" for x, y in vertices)


def case_text(n, name, power, reversible, support=2.8):
    dr = D / n
    layers = math.ceil(support - 1e-9)
    support_note = ("Table I's h = 2.8 dr is the support (the authors' code)" if support == 2.8
                    else "h = 2.8 dr (Table I); support 2h as eq. (17) prints" if support == 5.6
                    else "h = 2.8 dr (Table I); a support of the user's")
    courant = round(0.56 / support, 12)  # dt = h / (5 u1), h = 2.8 dr (Table I)
    shift = 17.1 * MM + D / 2 + dr / 2
    origin = f"[{fmt(-25 * MM)}, {fmt(-10 * MM)}]"
    radii = ", ".join(fmt(r * MM) for r in RADII)
    dissipation = ("viscosity = 0.0\nheat_conductivity = 0.0" if reversible else
                   "viscosity = 1.0e-4                 # mu (Table I)\n"
                   "heat_conductivity = 6.1997         # beta = d rho0 s0^2 / (200 u2) (Table I)")
    sources = "" if reversible else f'''
[superleak]
rate = 1.0e6                       # 1 / tau, tau = 1 us
centre = [0.0, 0.001]
half_width = 0.015
half_thickness = 0.002

[heater]
power = {power}                       # W/m
centre = [0.0, 0.008]
support = 0.004                    # 2H, H = 2 mm (Table I)
ramp_time = 0.02
'''
    run = "steps = 2000" if reversible else "t_end = 0.3"
    blocks = ""
    for index, (vertices, radius_line, mirror, sign) in enumerate(
            [(BODY, f"corner_radii = [{radii}]\n", False, -1),
             (BODY, f"corner_radii = [{radii}]\n", True, 1),
             (CAPILLARY_WALL, "", False, -1), (CAPILLARY_WALL, "", True, 1)], start=1):
        what = ["left glass body", "right glass body", "capillary's left wall",
                "capillary's right wall"][index - 1]
        body_layers = f"layers = {layers}\n" if vertices is BODY else ""
        blocks += f'''
[[particles]]                      # {index}: the {what}
kind = "dummy"
shape = "outline"
vertices = [{points(vertices)}]
{radius_line}{"mirror_x = true" + chr(10) if mirror else ""}offset = [{fmt(sign * shift)}, 0.0]
lattice_origin = {origin}
{body_layers}'''
    return f'''# The fountain effect of Kincl, Schmoranzer & Pavelka, Phys. Fluids 35 (2023) 047124,
# sec. III.C (Table I at T0 = 1.65 K), in the geometry the issue gives (mm, y up, the capillary
# on x = 0): a cryostat box x in [-25, 25], y from -10, open at the top, helium up to y = 23; two
# mirror-image glass bodies (adiabatic dummy shells, {layers} layers), each an L with rounded corners,
# and the capillary's walls, placed at x = xi - (17.1 + r_cap + dr / 2), r_cap = d / 2 = 0.775;
# the superleak |x| < 15, y = 1 +- 2, rate 1e6 / s; the heater, a Wendland kernel of support
# 4 mm at (0, 8), ramped over 0.02 s; the cryostat's walls the cooler (s0, free v_s: second
# sound and heat leave through them, as in the authors' fountain_2d.jl).
# dr = d / {n} (the paper: d / 40). Written by tools/plots/superfluid_fountain_case.py.{" The reversible core only: no dissipation, superleak or heater." if reversible else ""}
model = "superfluid"
dimension = 2
name = "{name}"

[physics]                          # Table I, fountain effect (T0 = 1.65 K)
rest_density = 145.2
first_sound_speed = 40.0
reference_temperature = 1.65
reference_entropy = 335.0
normal_fraction = 0.1934
normal_fraction_slope = 5.851e-4
heat_capacity = 1861.0             # eq. (14): u2 = 20.37 m/s
{dissipation}
gravity = 9.81                     # not given: standard gravity
cooler = "absorbing"               # the cryostat's walls as the authors' code has them
dummy_slip = "no_slip"             # the glass: no-slip for the normal fluid (authors' code)

[discretisation]
dr = {fmt(dr)}
{f"support_radius_over_dr = {support!r}".ljust(35)}# {support_note}
{f"courant_number = {courant!r}".ljust(35)}# dt = h / (5 u1), h = 2.8 dr (Table I)

[initial]
hydrostatic_surface = 0.023        # the helium's level

[jet]
height = 0.0337                    # the capillary's top: the jet speed is the volume rate above
{sources}
[domain]
min = [-0.03, -0.015]
max = [0.03, 0.125]

[[particles]]                      # 0: the helium, the bodies left out
kind = "fluid"
min = [-0.025, -0.010]
max = [0.025, 0.023]
exclude_blocks = [1, 2, 3, 4]
{blocks}
[[particles]]                      # the cryostat: no-slip walls at T0 (the cooler), open top
kind = "wall"
shape = "container"
layers = {layers}
open_top = true
min = [-0.025, -0.010]
max = [0.025, 0.120]

[run]
{run}

[output]
energy_every = {100 if reversible else 500}
snapshot_every = {1000 if reversible else 5000}
'''


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("n", type=int)
    parser.add_argument("name")
    parser.add_argument("power", type=float)
    parser.add_argument("--reversible", action="store_true")
    parser.add_argument("--support", type=float, default=2.8)
    parser.add_argument("--out", default=str(REPO / "models" / "superfluid" / "cases"))
    args = parser.parse_args()
    path = Path(args.out) / f"{args.name}.toml"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(case_text(args.n, args.name, args.power, args.reversible, args.support))
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
