#!/usr/bin/python3
"""Second sound with the superfluid model (paper 3 sec. III.B, eqs. 25-28, Figs. 5-6): the
standing entropy wave in a free square of side L = 1 cm at T0 = 1.9 K, to t = sqrt(2) L / u2.

Usage: /usr/bin/python3 tools/plots/superfluid_second_sound.py [--make-runs] [--runs DIR]
           [--out DIR] [--revsph PATH] [--threads N] [--only NAME ...]

--make-runs runs models/superfluid/cases/second-sound-small.toml with N particles per side
(dr = L / N), the kernel's support 3 dr (Table I's h as the authors' code uses it; "-2h" runs:
6 dr, eq. 17 as printed), dt = h / (M u1) with h = 3 dr, and amplitude A, into RUNS/NAME
(default RUNS = out/superfluid), to t = sqrt(2) L / u2 (one period of the mode); a run takes
M N steps of about N^2 particles. Runs:
  eps1-cosine-N{50,100,200}-A{0.001,0.01,0.1}, eps1-cosine-N300-A0.01
                                               M = 50, the adiabatic mode cos(pi x/L) cos(pi y/L)
  eps1-cosine-N{50,100,200}-A0.01-2h           the same with support 6 dr
  eps1-sine-N100-A0.01                         M = 50, eq. (26) as printed (sine)
  eps2-sine-N200-M{12.5,25,50,100}-A{0.01,0.1} the energy error against M (Fig. 5 right)
  probe-sine-N300-A0.01                        Fig. 6 with the sine start
Writes into --out (default docs/figures):
  superfluid_second_sound.png  eps1 against N for each A; eps2 against M for each A; the entropy
                               at (L/4, L/4) against time with eq. (25) (Fig. 6), and for the
                               sine runs the solution of the adiabatic square (below).
  superfluid_second_sound.csv  run, shape, N, M, A, eps1, eps2.
  superfluid_second_sound_probe.csv  run, time, entropy at the probe, eq. (25) there, for
                               every run (the figure's panel: the N = 300 runs, or the N = 100
                               ones at A = 0.01 until those exist).
  superfluid_second_sound.md   the numbers (also printed).

eps1 is eq. (27) with the sum over particles taken as an RMS (the model's second_sound_error),
its max over the outputs of the whole period and over the paper's window t <= sqrt(2) L / u1
(Table I's t_end); eps2 is eq. (28), max over the outputs of |E(t) / E(0) - 1|, E the sum of
eq. (15), over the same two windows. With free adiabatic edges, eq. (25) (sines, s = s0 on the edges) is not a
solution: no entropy crosses a free edge, so the edges keep dT/dn = 0 and the sine start splits
into the square's modes cos(m pi x/L) cos(n pi y/L). The script evaluates that series (m, n
even, 200 terms each) at the probe to show which one the sine runs follow.
"""

import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from revsph_runs import REPO, chosen_runs_main, read_csv, save_figure  # noqa: E402

CASE = REPO / "models" / "superfluid" / "cases" / "second-sound-small.toml"
L, S0, U1, U2 = 0.01, 725.5, 40.0, 18.83
PAPER_WINDOW = np.sqrt(2.0) * L / U1  # Table I's t_end for second sound


def command(shape, n, m, a, support=3.0):
    """dt = h / (M u1) with Table I's h = 3 dr whatever the support (courant_number is dt over
    support / u1)."""
    steps = int(round(m * n))
    return ["run", str(CASE), "--set", f"discretisation.dr={L / n!r}",
            "--set", f"discretisation.support_radius_over_dr={support!r}",
            "--set", f"discretisation.courant_number={3.0 / (support * m)!r}",
            "--set", f"initial.entropy_wave_amplitude={a}",
            "--set", f"initial.entropy_wave_shape={shape}",
            "--set", f"output.energy_every={max(1, steps // 200)}",
            "--set", f"output.snapshot_every={steps}"]


# (shape, N, M, A, support in dr); support 3 dr is Table I's h as the authors' code uses it,
# the "-2h" runs take eq. (17) as printed (support 2h = 6 dr).
RUNS = {}
for n in (50, 100, 200, 300):
    for a in ((0.001, 0.01, 0.1) if n < 300 else (0.01,)):
        RUNS[f"eps1-cosine-N{n}-A{a}"] = ("cosine", n, 50, a, 3.0)
for n in (50, 100, 200):
    RUNS[f"eps1-cosine-N{n}-A0.01-2h"] = ("cosine", n, 50, 0.01, 6.0)
RUNS["eps1-sine-N100-A0.01"] = ("sine", 100, 50, 0.01, 3.0)
for m in (12.5, 25, 50, 100):
    for a in (0.01, 0.1):
        RUNS[f"eps2-sine-N200-M{m}-A{a}"] = ("sine", 200, m, a, 3.0)
RUNS["probe-sine-N300-A0.01"] = ("sine", 300, 50, 0.01, 3.0)


def adiabatic_series(x, y, t, a, terms=200):
    """The sine start evolved in the square with adiabatic edges (linear theory)."""
    def c(m):
        return 2 / np.pi if m == 0 else 4 / (np.pi * (1 - m * m))
    total = np.zeros_like(t)
    for m in range(0, terms, 2):
        for n in range(0, terms, 2):
            total += (c(m) * c(n) * np.cos(m * np.pi * x / L) * np.cos(n * np.pi * y / L)
                      * np.cos(np.pi * U2 * np.hypot(m, n) * t / L))
    return S0 * (1 + a * total)


def write_rows(path, header, rows):
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(header)
        writer.writerows([v if isinstance(v, str) else f"{v:.10g}" for v in row] for row in rows)


def make_figures(runs, out, report, names):
    rows, probes = [], []
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.4))
    for name in names:
        shape, n, m, a, support = RUNS[name]
        diag = read_csv(runs / name / "diagnostics.csv")
        energy = read_csv(runs / name / "energy.csv")
        window = diag["time"] <= PAPER_WINDOW * (1 + 1e-9)
        eps1 = float(np.max(diag["second_sound_error"]))
        eps1_paper = float(np.max(diag["second_sound_error"][window]))
        total = energy["total"]
        eps2 = float(np.max(np.abs(total / total[0] - 1.0)))
        in_paper_window = energy["time"] <= PAPER_WINDOW * (1 + 1e-9)
        eps2_paper = float(np.max(np.abs(total[in_paper_window] / total[0] - 1.0)))
        rows.append((name, shape, n, m, a, support, eps1, eps1_paper, eps2, eps2_paper))
        probes.append((name, shape, n, a, diag))
    write_rows(out / "superfluid_second_sound.csv",
               ["run", "shape", "N", "M", "A", "support_over_dr", "eps1_period",
                "eps1_paper_window", "eps2_period", "eps2_paper_window"], rows)
    for r in rows:
        report.append((f"{r[0]}: eps1 (eq. 27 as an RMS) over the period / over t <= sqrt(2) L "
                       f"/ u1; eps2 (eq. 28) likewise",
                       f"{r[6]:.3e} / {r[7]:.3e}; {r[8]:.3e} / {r[9]:.3e}"))
    cosine_m50 = [r for r in rows if r[0].startswith("eps1-cosine")]
    for support in sorted({r[5] for r in cosine_m50}):
        for a in sorted({r[4] for r in cosine_m50 if r[5] == support}):
            pts = sorted((r[2], r[6], r[7]) for r in cosine_m50 if r[4] == a and r[5] == support)
            if len(pts) < 2 and support != 3.0:
                continue
            style = "o-" if support == 3.0 else "s--"
            line = axes[0].loglog([p[0] for p in pts], [p[1] for p in pts], style,
                                  label=f"A = {a}, support {support:g} dr, period")[0]
            if a == 0.01:
                axes[0].loglog([p[0] for p in pts], [p[2] for p in pts], ":",
                               marker=style[0], color=line.get_color(), mfc="none",
                               label=f"A = {a}, support {support:g} dr, t <= sqrt(2) L / u1")
    axes[0].axhline(0.01, color="grey", ls=":", label="1 % (the paper, N = 300)")
    axes[0].set(xlabel="N (particles per side)", ylabel="eps1 (RMS over particles)",
                title="cosine mode, M = 50")
    axes[0].legend(fontsize=7)
    eps2_rows = [r for r in rows if r[0].startswith("eps2")]
    for a in sorted({r[4] for r in eps2_rows}):
        pts = sorted((r[3], r[9]) for r in eps2_rows if r[4] == a)
        axes[1].loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=f"A = {a}")
    if eps2_rows:
        ms = np.array([12.5, 100])
        top = max(r[9] for r in eps2_rows)
        axes[1].loglog(ms, top * (ms / 12.5) ** -2, "k--", lw=0.8, label="slope -2")
    axes[1].set(xlabel="M (dt = h / (M u1))", ylabel="eps2 over t <= sqrt(2) L / u1",
                title="Fig. 5 right: energy error, N = 200, sine")
    axes[1].legend(fontsize=8)
    # Fig. 6 from the N = 300 runs, or, until they exist, from the N = 100 ones at A = 0.01.
    chosen = [p for p in probes if p[0] in ("eps1-cosine-N300-A0.01", "probe-sine-N300-A0.01")] or [
        p for p in probes if p[0] in ("eps1-cosine-N100-A0.01", "eps1-sine-N100-A0.01")]
    for name, shape, n, a, diag in chosen:
        t = diag["time"]
        axes[2].plot(t * 1e3, diag["probe_entropy"], label=f"SPH, {shape}")
        axes[2].plot(t * 1e3, diag["probe_entropy_exact"], "--", label=f"eq. (25), {shape}")
        if shape == "sine":
            axes[2].plot(t * 1e3, adiabatic_series(L / 4, L / 4, t, a), ":",
                         label="adiabatic square, sine start")
    # Every run's series (the simulated second-sound speed is fitted to them:
    # superfluid_second_sound_speed.py).
    probe_rows = [(name, diag["time"][i], diag["probe_entropy"][i], diag["probe_entropy_exact"][i])
                  for name, _, _, _, diag in probes for i in range(len(diag["time"]))]
    if probes:
        write_rows(out / "superfluid_second_sound_probe.csv",
                   ["run", "time", "probe_entropy", "eq25"], probe_rows)
    axes[2].axvline(PAPER_WINDOW * 1e3, color="grey", ls=":", lw=0.8)
    axes[2].set(xlabel="t (ms)", ylabel="s at (L/4, L/4) (J/(kg K))",
                title=f"Fig. 6: A = 0.01, M = 50, N = {chosen[0][2] if chosen else 300}")
    axes[2].legend(fontsize=7)
    save_figure(fig, out / "superfluid_second_sound.png")


def main():
    return chosen_runs_main(__doc__, "out/superfluid", RUNS, lambda name: command(*RUNS[name]),
                            make_figures, "superfluid_second_sound.md")


if __name__ == "__main__":
    sys.exit(main())
