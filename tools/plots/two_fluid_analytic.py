#!/usr/bin/python3
"""Paper 5's two analytic figures (Tsuzuki 2021, sec. V.2): Fig. 6, the exact entropy wave
S(x, y, t) of eqs. (45)-(47), mode (4, 3), over half a period; Fig. 9, the Mach number Ma against
the volume fluctuation rate dD from eq. (48). Formulas only, no runs (about a second).

Usage: /usr/bin/python3 tools/plots/two_fluid_analytic.py [--out DIR]

Writes into --out (default docs/figures):
  two_fluid_fig6.csv  one row per time lambda t = 0, pi/10, ..., pi (half the period
                      T = 2 pi / lambda = 2 / (5 c)): t / T, t for c = 135 and 20 m/s, A(t) of
                      eq. (46), the largest and smallest S on the paper's 400 x 400 particle
                      centres ((i + 1/2) / 400), and S at (0.3, 0.4) (the point of Fig. 7).
  two_fluid_fig6.png  (a)-(e) S(x, y) at lambda t = 0, pi/4, pi/2, 3 pi/4, pi as the paper's
                      snapshots; (f) A(t) = cos(lambda t) and S(0.3, 0.4, t) over the half period.
  two_fluid_fig9.csv  dD = 0 ... 3 % (the range of Figs. 7-8) in steps of 0.05 %: Ma of eq. (48)
                      and its small-dD form sqrt(2 dD / 100).
  two_fluid_fig9.png  Ma against dD with the paper's marked point (dD = 0.5 %, Ma = 0.1) and
                      eq. (48)'s own dD at Ma = 0.1.

The exact solution is the one the entropy-wave benchmark uses as its reference
(tools/analysis/two_fluid_entropy_wave.{hpp,cpp}: S_a = cos(lambda t) sin(4 pi x) sin(3 pi y),
lambda = 5 c pi; C++ only): it is written again here and checked against the exact_amplitude
column (cos(lambda t_end), t_end = 0.03 s) of docs/figures/two_fluid_entropy_wave.csv.
"""

import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from docstring_cli import parser_from_docstring  # noqa: E402

REPO = Path(__file__).resolve().parents[2]
MODE = (4, 3)          # (m, n), sec. V.2
SIDES = (1.0, 1.0)     # (L_x, L_y)
PER_SIDE = 400         # (N_px, N_py)
SPEEDS = (135.0, 20.0)  # c [m/s]
T_END = 0.03           # s, the time of Fig. 8's E_r
PROBE = (0.3, 0.4)     # the benchmark's probe (Fig. 7)


def wave_rate(speed, mode=MODE, sides=SIDES):
    """lambda_{m,n} = c pi sqrt(m^2 / L_x^2 + n^2 / L_y^2), eq. (47)."""
    return speed * np.pi * np.hypot(mode[0] / sides[0], mode[1] / sides[1])


def amplitude(phase, sine=0.0, cosine=1.0):
    """A(t) = C sin(lambda t) + C* cos(lambda t), eq. (46), of phase = lambda t; the benchmark
    starts at rest, C = 0, C* = 1."""
    return sine * np.sin(phase) + cosine * np.cos(phase)


def entropy_wave(x, y, phase, mode=MODE, sides=SIDES):
    """S(x, y, t) = A(t) sin(m pi x / L_x) sin(n pi y / L_y), eq. (45)."""
    return (amplitude(phase) * np.sin(mode[0] * np.pi * x / sides[0])
            * np.sin(mode[1] * np.pi * y / sides[1]))


def mach(fluctuation):
    """Ma = sqrt(2 (1 - 1 / (dD / 100 + 1))), eq. (48), dD in per cent."""
    return np.sqrt(2.0 * (1.0 - 1.0 / (np.asarray(fluctuation) / 100.0 + 1.0)))


def fluctuation_of(ma):
    """eq. (48) solved for dD [%]: 100 (1 / (1 - Ma^2 / 2) - 1)."""
    return 100.0 * (1.0 / (1.0 - 0.5 * np.asarray(ma) ** 2) - 1.0)


def check_against_benchmark(report):
    """cos(lambda t_end) here against the C++ tool's exact_amplitude column."""
    path = REPO / "docs" / "figures" / "two_fluid_entropy_wave.csv"
    if not path.is_file():
        report.append(f"check skipped: {path} missing")
        return
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    worst = 0.0
    for speed in SPEEDS:
        tool = {float(r["exact_amplitude"]) for r in rows if float(r["speed"]) == speed}
        mine = amplitude(wave_rate(speed) * T_END)
        worst = max([worst] + [abs(v - mine) for v in tool])
        report.append(f"check c = {speed:g}: A(0.03 s) = {mine:.12f} here, "
                      f"{sorted(tool)} in two_fluid_entropy_wave.csv")
    if worst > 1e-11:
        raise SystemExit(f"exact amplitude differs from the benchmark's by {worst:.3g}")


def figure6(out, report):
    centres = (np.arange(PER_SIDE) + 0.5) / PER_SIDE
    x, y = np.meshgrid(centres, centres)
    rows = []
    for k in range(11):
        phase = np.pi * k / 10
        s = entropy_wave(x, y, phase)
        rows.append({"phase_over_pi": k / 10, "t_over_period": k / 20,
                     **{f"t_ms_c{c:g}": 1e3 * phase / wave_rate(c) for c in SPEEDS},
                     "A": amplitude(phase), "S_max": s.max(), "S_min": s.min(),
                     "S_probe": entropy_wave(*PROBE, phase)})
    with open(out / "two_fluid_fig6.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows({k: f"{v:.10g}" for k, v in r.items()} for r in rows)
    for r in rows:
        if r["phase_over_pi"] in (0.0, 0.5, 1.0):
            report.append(f"Fig. 6: lambda t = {r['phase_over_pi']:g} pi (t = "
                          f"{r['t_ms_c135']:.4f} ms at c = 135, {r['t_ms_c20']:.4f} ms at c = 20):"
                          f" A = {r['A']:+.6f}, S on the 400^2 centres in [{r['S_min']:+.6f}, "
                          f"{r['S_max']:+.6f}], S(0.3, 0.4) = {r['S_probe']:+.6f}")
    for c in SPEEDS:
        period = 2e3 * np.pi / wave_rate(c)
        report.append(f"c = {c:g}: lambda = {wave_rate(c):.3f} 1/s, period {period:.4f} ms, "
                      f"half period {1e3 * np.pi / wave_rate(c):.4f} ms")

    fig, axes = plt.subplots(2, 3, figsize=(13, 8.6), layout="constrained")
    names = ("0", "$\\pi$/4", "$\\pi$/2", "3$\\pi$/4", "$\\pi$")
    for ax, k, letter in zip(axes.flat, range(5), "abcde"):
        phase = np.pi * k / 4
        image = ax.imshow(entropy_wave(x, y, phase), origin="lower", extent=(0, 1, 0, 1),
                          cmap="RdBu_r", vmin=-1, vmax=1)
        ax.plot(*PROBE, "k+", markersize=8)
        ax.set(xlabel="x / L_x", ylabel="y / L_y",
               title=f"({letter}) $\\lambda t$ = {names[k]}, t = {k / 8:g} T\n"
                     f"({1e3 * phase / wave_rate(135):.3f} ms at c = 135, "
                     f"{1e3 * phase / wave_rate(20):.2f} ms at c = 20)")
        ax.title.set_fontsize(9)
    fig.colorbar(image, ax=axes[:, 2], shrink=0.5, location="right", label="S")
    ax = axes[1, 2]
    phase = np.linspace(0, np.pi, 401)
    ax.plot(phase / np.pi, amplitude(phase), label="A(t) = cos($\\lambda t$), eq. (46)")
    ax.plot(phase / np.pi, entropy_wave(*PROBE, phase), label="S(0.3, 0.4, t) (Fig. 7's point)")
    ax.plot(np.arange(5) / 4, amplitude(np.pi * np.arange(5) / 4), "ko", label="snapshots (a)-(e)")
    ax.set(xlabel="$\\lambda t / \\pi$ (1 = half period T / 2 = 1 / (5 c))", ylabel="S",
           title="(f) amplitude over the half period")
    ax.title.set_fontsize(9)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    fig.suptitle("Paper 5, Fig. 6: exact entropy wave, eqs. (45)-(47), mode (4, 3), L = 1, "
                 "C = 0, C* = 1 (+: Fig. 7's point)", fontsize=10)
    fig.savefig(out / "two_fluid_fig6.png", dpi=110)
    plt.close(fig)


def figure9(out, report):
    fluctuation = np.round(np.arange(0, 3.0001, 0.05), 10)
    ma = mach(fluctuation)
    small = np.sqrt(2 * fluctuation / 100)
    with open(out / "two_fluid_fig9.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["dD_percent", "Ma_eq48", "Ma_small_dD"])
        writer.writerows([f"{d:g}", f"{m:.10g}", f"{s:.10g}"]
                         for d, m, s in zip(fluctuation, ma, small))
    at_point = fluctuation_of(0.1)
    assert abs(mach(at_point) - 0.1) < 1e-14  # the inverse inverts (48)
    # the paper's reading off its figure, against the formula
    report.append(f"Fig. 9: eq. (48) at Ma = 0.1 gives dD = {at_point:.5f} % (paper: "
                  f"'approximately 0.5', {100 * (1 - 0.5 / at_point):.2f} % below it); "
                  f"at dD = 0.5 % Ma = {mach(0.5):.6f}")
    report.append(f"Fig. 9: Ma(dD = 3 %) = {mach(3.0):.5f}, Ma(dD = 2 %) = {mach(2.0):.5f}; "
                  f"the small-dD form sqrt(2 dD / 100) is {small[-1] / ma[-1] - 1:+.2%} off at 3 %")
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    dense = np.linspace(0, 3, 601)
    ax.plot(dense, mach(dense), label="eq. (48): Ma = $\\sqrt{2(1 - 1/(\\delta D/100 + 1))}$")
    ax.plot(dense, np.sqrt(2 * dense / 100), ":",
            label="small $\\delta D$: $\\sqrt{2\\,\\delta D/100}$")
    ax.plot([0.5], [0.1], "k*", markersize=11, label="paper: $\\delta D$ = 0.5 % at Ma = 0.1")
    ax.plot([at_point], [0.1], "ro", mfc="none", markersize=8,
            label=f"eq. (48) at Ma = 0.1: $\\delta D$ = {at_point:.4f} %")
    ax.axhline(0.1, color="0.6", linewidth=0.7)
    ax.set(xlabel="volume fluctuation rate $\\delta D$ [%]", ylabel="Ma",
           title="Paper 5, Fig. 9: Ma against $\\delta D$, eq. (48)", xlim=(0, 3), ylim=(0, None))
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    fig.savefig(out / "two_fluid_fig9.png", dpi=120)
    plt.close(fig)


def main():
    parser = parser_from_docstring(__doc__)
    parser.add_argument("--out")
    args = parser.parse_args()
    out = Path(args.out or REPO / "docs" / "figures")
    out.mkdir(parents=True, exist_ok=True)
    report = []
    check_against_benchmark(report)
    figure6(out, report)
    figure9(out, report)
    print("\n".join(report))
    print(f"wrote {out}/two_fluid_fig6.csv, .png and two_fluid_fig9.csv, .png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
