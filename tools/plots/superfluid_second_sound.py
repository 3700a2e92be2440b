#!/usr/bin/python3
"""Second sound with the superfluid model (paper 3 sec. III.B, eqs. 25-28, Figs. 5-6): the
standing entropy wave in a free square of side L = 1 cm at T0 = 1.9 K, to t = sqrt(2) L / u2.

Usage: /usr/bin/python3 tools/plots/superfluid_second_sound.py [--make-runs] [--runs DIR]
           [--out DIR] [--revsph PATH] [--threads N] [--only NAME ...]

--make-runs runs models/superfluid/cases/second-sound-small.toml with N particles per side
(dr = L / N), dt = h / (M u1) (courant_number = 1 / (2 M): the case's support is 2h) and
amplitude A, into RUNS/NAME (default RUNS = out/superfluid); a run takes M N steps of about N^2
particles (N = 100, M = 50: 3 minutes on one thread; N = 200: 25; N = 300: 90). Runs:
  eps1-cosine-N{50,100,200}-A{0.001,0.01,0.1}  M = 50, the adiabatic mode cos(pi x/L) cos(pi y/L)
  eps1-sine-N100-A0.01                         M = 50, eq. (26) as printed (sine)
  eps2-sine-N100-M{12.5,25,50,100}-A{0.01,0.1} the energy error against M (the paper: N = 200)
  probe-cosine-N300-A0.01, probe-sine-N300-A0.01  Fig. 6: the entropy at (L/4, L/4)
Writes into --out (default docs/figures):
  superfluid_second_sound.png  eps1 against N for each A; eps2 against M for each A; the entropy
                               at (L/4, L/4) against time with eq. (25) (Fig. 6), and for the
                               sine runs the solution of the adiabatic square (below).
  superfluid_second_sound.csv  run, shape, N, M, A, eps1, eps2.
  superfluid_second_sound_probe.csv  run, time, entropy at the probe, eq. (25) there (the
                               N = 300 runs, or the N = 100 ones at A = 0.01 until those exist).
  superfluid_second_sound.md   the numbers (also printed).

eps1 is eq. (27) with the sum over particles taken as an RMS (the model's second_sound_error,
the max over the outputs); eps2 is eq. (28), max over the outputs of |E(t) / E(0) - 1|, E the
sum of eq. (15). With free adiabatic edges, eq. (25) (sines, s = s0 on the edges) is not a
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
from revsph_runs import REPO, chosen_runs, figure_parser, figure_script_main, read_csv, save_figure  # noqa: E402

CASE = REPO / "models" / "superfluid" / "cases" / "second-sound-small.toml"
L, S0, U2 = 0.01, 725.5, 18.83


def command(shape, n, m, a):
    steps = int(round(m * n))
    return ["run", str(CASE), "--set", f"discretisation.dr={L / n!r}",
            "--set", f"discretisation.courant_number={1.0 / (2.0 * m)!r}",
            "--set", f"initial.entropy_wave_amplitude={a}",
            "--set", f"initial.entropy_wave_shape={shape}",
            "--set", f"output.energy_every={max(1, steps // 200)}",
            "--set", f"output.snapshot_every={steps}"]


RUNS = {}
for n in (50, 100, 200):
    for a in (0.001, 0.01, 0.1):
        RUNS[f"eps1-cosine-N{n}-A{a}"] = ("cosine", n, 50, a)
RUNS["eps1-sine-N100-A0.01"] = ("sine", 100, 50, 0.01)
for m in (12.5, 25, 50, 100):
    for a in (0.01, 0.1):
        RUNS[f"eps2-sine-N100-M{m}-A{a}"] = ("sine", 100, m, a)
RUNS["probe-cosine-N300-A0.01"] = ("cosine", 300, 50, 0.01)
RUNS["probe-sine-N300-A0.01"] = ("sine", 300, 50, 0.01)


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
        shape, n, m, a = RUNS[name]
        diag = read_csv(runs / name / "diagnostics.csv")
        energy = read_csv(runs / name / "energy.csv")
        eps1 = float(np.max(diag["second_sound_error"]))
        total = energy["total"]
        eps2 = float(np.max(np.abs(total / total[0] - 1.0)))
        rows.append((name, shape, n, m, a, eps1, eps2))
        probes.append((name, shape, n, a, diag))
    write_rows(out / "superfluid_second_sound.csv", ["run", "shape", "N", "M", "A", "eps1", "eps2"],
               rows)
    for r in rows:
        report.append((f"{r[0]}: eps1 (eq. 27 as an RMS), eps2 (eq. 28)",
                       f"{r[5]:.3e}, {r[6]:.3e}"))
    cosine_m50 = [r for r in rows if r[0].startswith(("eps1-cosine", "probe-cosine"))]
    for a in sorted({r[4] for r in cosine_m50}):
        pts = sorted((r[2], r[5]) for r in cosine_m50 if r[4] == a)
        axes[0].loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=f"A = {a}")
    axes[0].axhline(0.01, color="grey", ls=":", label="1 % (the paper, N = 300)")
    axes[0].set(xlabel="N (particles per side)", ylabel="eps1 (RMS over particles)",
                title="cosine mode, M = 50")
    axes[0].legend(fontsize=8)
    for a in sorted({r[4] for r in rows if r[0].startswith("eps2")}):
        pts = sorted((r[3], r[6]) for r in rows if r[0].startswith("eps2") and r[4] == a)
        axes[1].loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=f"A = {a}")
    if any(r[0].startswith("eps2") for r in rows):
        ms = np.array([12.5, 100])
        axes[1].loglog(ms, 1e-7 * (ms / 12.5) ** -2, "k--", lw=0.8, label="slope -2")
    axes[1].set(xlabel="M (dt = h / (M u1))", ylabel="eps2", title="energy error, N = 100, sine")
    axes[1].legend(fontsize=8)
    # Fig. 6 from the N = 300 runs, or, until they exist, from the N = 100 ones at A = 0.01.
    chosen = [p for p in probes if p[0].startswith("probe")] or [
        p for p in probes if p[0] in ("eps1-cosine-N100-A0.01", "eps1-sine-N100-A0.01")]
    probe_rows = []
    for name, shape, n, a, diag in chosen:
        t = diag["time"]
        axes[2].plot(t * 1e3, diag["probe_entropy"], label=f"SPH, {shape}")
        axes[2].plot(t * 1e3, diag["probe_entropy_exact"], "--", label=f"eq. (25), {shape}")
        if shape == "sine":
            axes[2].plot(t * 1e3, adiabatic_series(L / 4, L / 4, t, a), ":",
                         label="adiabatic square, sine start")
        probe_rows += [(name, t[i], diag["probe_entropy"][i], diag["probe_entropy_exact"][i])
                       for i in range(len(t))]
    if probes:
        write_rows(out / "superfluid_second_sound_probe.csv",
                   ["run", "time", "probe_entropy", "eq25"], probe_rows)
    axes[2].set(xlabel="t (ms)", ylabel="s at (L/4, L/4) (J/(kg K))",
                title=f"Fig. 6: A = 0.01, M = 50, N = {chosen[0][2] if chosen else 300}")
    axes[2].legend(fontsize=7)
    save_figure(fig, out / "superfluid_second_sound.png")


def main():
    parser = figure_parser(__doc__, "out/superfluid", REPO / "docs" / "figures", RUNS)
    args = parser.parse_args()
    names = chosen_runs(parser, args, RUNS)
    table = {n: command(*RUNS[n]) for n in names}
    return figure_script_main(
        args, table,
        [(names, lambda runs, out, report: make_figures(runs, out, report, names))],
        "superfluid_second_sound.md")


if __name__ == "__main__":
    sys.exit(main())
