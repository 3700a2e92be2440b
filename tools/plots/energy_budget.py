#!/usr/bin/python3
"""Energy budget of a dam break (paper 1, Figs. 8-12 and Fig. 5).

Usage: /usr/bin/python3 tools/plots/energy_budget.py RUN_DIR [RUN_DIR ...] [--label TEXT ...]
           [--out DIR] [--tag TEXT]

Each RUN_DIR is the output of `revsph verify --out` (forward/ and backward/) or of `revsph run`
(forward only); give the same case at several time steps (dt, dt/2, dt/4) to see the dt
dependence of Fig. 5. One --label per RUN_DIR, in order (default: the case name and dt).

Writes, into --out (default FIRST_RUN_DIR/analysis):
  energy_budget{TAG}.png  Figs. 8-12 for the first RUN_DIR: the relative total-energy error
                          |E - E0| / |E0|, and the kinetic, gravitational, compressional and wall
                          energies, forward and reversed, the reversed run drawn against the
                          forward-equivalent time 2 t_rev - t so that it lies on top of the
                          forward one; a sixth panel shows how far apart the two are.
  energy_drift{TAG}.png   Fig. 5: (E(t) - E(0)) / (E_g(0) - E_g(t_end)), forward run, one curve
                          per RUN_DIR.
and prints, per RUN_DIR, the largest forward relative error and the largest |Fig. 5 quantity|.

Energies are per unit depth (J/m) in 2D. E0 includes the compressional energy of the fluid at
rest, which is large (4.8e6 J/m for the dam break), so the relative error is small compared with
the energy that actually moves around; Fig. 5 normalises by the potential energy released
instead (the convention of the energy-dissipation studies the paper cites), which shows the
error on the scale of the flow. The normaliser is the net drop E_g(0) - E_g(t_end) over the
forward run, not the largest drop, so it is the energy the run converted by its end.
"""

import csv
import json
import sys
from pathlib import Path

from docstring_cli import parser_from_docstring

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

FORWARD = "tab:blue"
BACKWARD = "tab:orange"
COMPONENTS = ("kinetic", "gravitational", "compressional", "wall", "total")
DPI = 110


def read_energy(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{path}: no rows")
    # Header cells are `name [unit]`: columns by name.
    data = {name.split(" [")[0]: np.array([float(r[name]) for r in rows]) for name in rows[0]}
    data["step"] = data["step"].astype(np.int64)
    return data


class Run:
    """One run directory: forward energy rows, backward rows (None for a plain run), summary."""

    def __init__(self, directory, label=None):
        self.dir = Path(directory)
        if (self.dir / "forward" / "energy.csv").is_file():
            self.forward = read_energy(self.dir / "forward" / "energy.csv")
            backward = self.dir / "backward" / "energy.csv"
            self.backward = read_energy(backward) if backward.is_file() else None
        elif (self.dir / "energy.csv").is_file():
            self.forward, self.backward = read_energy(self.dir / "energy.csv"), None
        else:
            sys.exit(f"{self.dir}: neither forward/energy.csv nor energy.csv")
        summary = self.dir / "summary.json"
        self.summary = json.loads(summary.read_text()) if summary.is_file() else {}
        self.dt = self.summary.get("dt")
        if self.dt is None and len(self.forward["step"]) > 1:
            steps = self.forward["step"][1] - self.forward["step"][0]
            self.dt = (self.forward["time"][1] - self.forward["time"][0]) / steps
        self.label = label or self.default_label()

    def default_label(self):
        case = self.summary.get("case", self.dir.name)
        arithmetic = self.summary.get("arithmetic", "fixed")
        text = f"{case}, dt = {self.dt:.3g} s" if self.dt else case
        return text + (", float" if arithmetic == "float" else "")

    def case_key(self):
        return (self.summary.get("case", self.dir.name), self.summary.get("arithmetic"),
                tuple(o for o in self.summary.get("overrides", [])
                      if not o.startswith(("output.", "discretisation.courant_number",
                                           "discretisation.dt"))))

    def turning_time(self):
        return self.forward["time"][-1]

    def backward_equivalent_time(self):
        """The backward phase continues the time count from the turning point (t_rev .. 2 t_rev),
        and its row at t corresponds to the forward state at 2 t_rev - t."""
        start = self.backward["time"][0]
        return 2.0 * start - self.backward["time"]

    def max_relative_error(self):
        return float(np.max(self.forward["relative_error"]))

    def max_mechanical_relative_error(self):
        """max |E - E0| over the energy that moved (docs/verify.md); nan for an energy.csv
        written before the column existed."""
        if "mechanical_relative_error" not in self.forward:
            return float("nan")
        return float(np.max(self.forward["mechanical_relative_error"]))

    def potential_drop(self):
        return self.forward["gravitational"][0] - self.forward["gravitational"][-1]

    def normalised_drift(self):
        return (self.forward["total"] - self.forward["total"][0]) / self.potential_drop()


def reversal_mismatch(run, name):
    """(forward-equivalent time, |backward - forward|) of one energy column at equal
    forward-equivalent steps. The backward row at step s matches the forward row at step
    2 s_rev - s; the two meet at the turning point."""
    s_rev = run.backward["step"][0]
    forward = {s: (t, value) for s, t, value in
               zip(run.forward["step"].tolist(), run.forward["time"], run.forward[name])}
    times, differences = [], []
    for s, value in zip(run.backward["step"].tolist(), run.backward[name]):
        if 2 * s_rev - s in forward:
            t, forward_value = forward[2 * s_rev - s]
            times.append(t)
            differences.append(abs(value - forward_value))
    return np.array(times), np.array(differences)


def budget_figure(run, path):
    fig, axes = plt.subplots(2, 3, figsize=(13, 7.2))
    panels = [
        ("relative_error", "|E − E(0)| / |E(0)|", "Fig. 8: total energy, relative error"),
        ("kinetic", "kinetic energy (J/m)", "Fig. 9: kinetic energy"),
        ("gravitational", "gravitational energy (J/m)", "Fig. 10: gravitational energy"),
        ("compressional", None, "Fig. 11: compressional (internal) energy"),
        ("wall", "wall energy (J/m)", "Fig. 12: wall–fluid energy"),
    ]
    # The compressional energy of the fluid at rest is a large constant; its change is the signal.
    offset = run.forward["compressional"][0]
    for ax, (name, ylabel, title) in zip(axes.flat, panels):
        shift = offset if name == "compressional" else 0.0
        if name == "compressional":
            ylabel = f"E_c − E_c(0)  (J/m; E_c(0) = {offset:.4g})"
        ax.plot(run.forward["time"], run.forward[name] - shift, "-", color=FORWARD, lw=2.2,
                label="forward")
        if run.backward is not None:
            ax.plot(run.backward_equivalent_time(), run.backward[name] - shift, "--",
                    color=BACKWARD, lw=1.2, label="reversed (rev), at 2 t_rev − t")
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("forward-equivalent time t (s)")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        ax.ticklabel_format(axis="y", style="sci", scilimits=(-3, 4))
    axes.flat[0].legend(fontsize=8, loc="upper left")
    axes.flat[0].annotate(f"max {run.max_relative_error():.3g} (forward)", (0.98, 0.04),
                          xycoords="axes fraction", ha="right", fontsize=8)

    ax = axes.flat[5]
    ax.set_title("reversed against forward, same forward-equivalent step", fontsize=9)
    if run.backward is None:
        ax.text(0.5, 0.5, "no backward phase (plain run)", ha="center", va="center",
                transform=ax.transAxes)
        ax.set_axis_off()
    else:
        lines = []
        for name, colour in zip(COMPONENTS, ("C0", "C1", "C2", "C3", "k")):
            t, difference = reversal_mismatch(run, name)
            lines.append(f"{name}: max |Δ| = {difference.max():.3g} J/m")
            positive = difference > 0
            if positive.any():
                ax.semilogy(t[positive], difference[positive], ".", ms=3, color=colour,
                            label=f"{name} (max {difference.max():.2g})")
        if ax.has_data():
            ax.set_xlabel("forward-equivalent time t (s)")
            ax.set_ylabel("|E_rev − E_forward| (J/m)")
            ax.legend(fontsize=7, loc="lower left")
            ax.grid(alpha=0.3)
        else:
            ax.set_axis_off()
            ax.text(0.5, 0.5, "every energy of the reversed run equals the forward one\n"
                    "at the same forward-equivalent step, to the last bit\n\n" + "\n".join(lines),
                    ha="center", va="center", transform=ax.transAxes, fontsize=9)
    arithmetic = {"fixed": "fixed point", "float": "floating point"}.get(
        run.summary.get("arithmetic"), "arithmetic not recorded")
    fig.suptitle(f"Energy budget, {run.label} ({arithmetic}), velocities reversed at "
                 f"t_rev = {run.turning_time():g} s", fontsize=11)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def drift_figure(runs, path):
    several = len({run.dt for run in runs}) > 1
    fig, axes = plt.subplots(1, 2 if several else 1, figsize=(12 if several else 7.5, 4.6),
                             squeeze=False, gridspec_kw={"width_ratios": [1.6, 1]} if several
                             else None)
    ax = axes[0][0]
    for i, run in enumerate(runs):
        peak = np.max(np.abs(run.normalised_drift()))
        ax.plot(run.forward["time"], run.normalised_drift(), lw=1.1, color=f"C{i}",
                label=f"{run.label}  (max |·| {peak:.2g})")
    ax.axhline(0.0, color="0.5", lw=0.8)
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("(E(t) − E(0)) / (E_g(0) − E_g(t_end))")
    ax.set_title("Fig. 5: total energy change relative to the potential energy released",
                 fontsize=10)
    ax.ticklabel_format(axis="y", style="sci", scilimits=(-3, 3))
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)

    if several:
        # The bound of a second-order symplectic scheme's energy error scales as dt^2.
        ax = axes[0][1]
        dts = np.array([run.dt for run in runs])
        peaks = np.array([np.max(np.abs(run.normalised_drift())) for run in runs])
        for i, run in enumerate(runs):
            ax.loglog(dts[i], peaks[i], "o", color=f"C{i}", ms=7)
        # One dt^2 line per case: runs of different resolutions have different constants.
        cases = {}
        for i, run in enumerate(runs):
            cases.setdefault(run.case_key(), []).append(i)
        for members in cases.values():
            if len({dts[i] for i in members}) < 2:
                continue
            anchor = max(members, key=lambda i: dts[i])
            line = np.array([min(dts[i] for i in members), dts[anchor]])
            ax.loglog(line, peaks[anchor] * (line / dts[anchor]) ** 2, "--", color="0.5",
                      label=f"∝ dt², {runs[anchor].case_key()[0]}")
        ax.set_xlabel("time step dt (s)")
        ax.set_ylabel("max over the run of |Fig. 5 quantity|")
        ax.set_title("the bound decreases with the time step", fontsize=10)
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def main(argv=None):
    parser = parser_from_docstring(__doc__)
    parser.add_argument("run_dirs", nargs="+", metavar="RUN_DIR")
    parser.add_argument("--label", action="append", default=[],
                        help="legend label of a RUN_DIR (one per RUN_DIR, in order)")
    parser.add_argument("--out", help="output directory (default FIRST_RUN_DIR/analysis)")
    parser.add_argument("--tag", default="", help="appended to the PNG file names")
    args = parser.parse_args(argv)
    if len(args.label) > len(args.run_dirs):
        parser.error("more --label than RUN_DIRs")
    labels = args.label + [None] * (len(args.run_dirs) - len(args.label))
    runs = [Run(d, label) for d, label in zip(args.run_dirs, labels)]
    out = Path(args.out) if args.out else runs[0].dir / "analysis"
    out.mkdir(parents=True, exist_ok=True)

    budget = out / f"energy_budget{args.tag}.png"
    drift = out / f"energy_drift{args.tag}.png"
    budget_figure(runs[0], budget)
    drift_figure(runs, drift)
    for run in runs:
        print(f"{run.dir}: {run.label}: max relative total-energy error (forward) "
              f"{run.max_relative_error():.6g}; max mechanical relative error (forward) "
              f"{run.max_mechanical_relative_error():.6g}; max |E - E0| / (E_g(0) - E_g(t_end)) "
              f"{np.max(np.abs(run.normalised_drift())):.6g} "
              f"(E_g drop {run.potential_drop():.6g} J/m)")
    print(f"wrote {budget}, {drift}")


if __name__ == "__main__":
    main()
