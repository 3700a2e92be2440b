"""Rayleigh-Taylor with Tsuzuki's two-fluid model (paper 5 sec. V.1, Fig. 5): the paper's run (the
mushroom and its tilt at t sqrt(g / L_x) = 2.34), and the classical limit: the early growth rate
of a small cosine perturbation against sqrt(A k g).

Usage: /usr/bin/python3 tools/plots/two_fluid_rayleigh_taylor.py [--make-runs] [--runs DIR]
           [--out DIR] [--revsph PATH] [--threads N] [--only NAME ...]

--make-runs runs models/two_fluid/cases/rayleigh-taylor-linear.toml (superfluid above normal
fluid, the two-fluid couplings off, 96 x 192 particles, amplitude 1 um, to 5 ms; half a minute
on one thread) into RUNS/NAME (default RUNS = out/two_fluid). Runs:
  rt-linear-n96     the case as it is (L_x / dr = 96)
  rt-linear-n192    dr halved (L_x / dr = 192; about 5 minutes on one thread)
  rt-hydro-nN       the case from hydrostatic equilibrium (initial.hydrostatic = true: each
                    particle's mass compressed to its column's pressure), L_x / dr = N = 96,
                    144, 192
  rt-mode-nN        the same with the interface moved by its linear mode's displacement
                    (interface.perturbation = "displacement": a smooth interface, not a
                    staircase of lattice rows)
  rt-linear-n96-pb0.05, rt-mode-n96-pbP
                    the background pressure 0.05 Pa (the case: 0.2), and P = 0.05, 0.02 Pa
  rt-ka0.1-nN-pbP   the mode start at k a = 0.1 (amplitude 1.6 um, 1.5 to 3 spacings), N = 96,
                    144, 192, background pressure P = 0 or 0.02 Pa
  rt-paper          models/two_fluid/cases/rayleigh-taylor.toml: 240 x 480 particles, every
                    coupling on, to 7.49 ms (20 to 60 minutes on one thread)
Writes into --out (default docs/figures):
  two_fluid_rayleigh_taylor.png         the paper's run at its snapshots (Fig. 5): (a) the kinds,
                                        (b) the magnitude of eq. (34)'s viscosity term (the
                                        `viscous_acceleration` view), (c) the speed
  two_fluid_rayleigh_taylor.csv         the paper's run: t, the interface's lowest superfluid
                                        and highest normal particle (the spike and the bubble)
  two_fluid_rayleigh_taylor_growth.png  the interface's sin(k x) amplitude against t with the
                                        fitted a0 cosh(sigma t) and the classical curve
  two_fluid_rayleigh_taylor_growth.csv  run, t, amplitude
  two_fluid_rayleigh_taylor.md          sigma per run against sqrt(A k g) (also printed)

The interface height in each of 24 columns is the midpoint between the lowest superfluid and the
highest normal particle there; its amplitude is the sin(k x) coefficient over the box (the box is
shifted by L_x / 4, so that is the box's cosine mode). Linear theory for an interface released
from rest: a(t) = a0 cosh(sigma t), sigma = sqrt(A k g), A = (rho_s - rho_n) / (rho_s + rho_n).
The fit takes the snapshots while k |a| < 0.15 (small slope: nonlinear terms below (k a)^2 = 2 %).
"""

import csv
import sys
from pathlib import Path

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.optimize import curve_fit  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from revsph_runs import REPO, chosen_runs_main, save_figure, snapshots  # noqa: E402

CASE = REPO / "models" / "two_fluid" / "cases" / "rayleigh-taylor-linear.toml"
PAPER_CASE = REPO / "models" / "two_fluid" / "cases" / "rayleigh-taylor.toml"
RHO_S, RHO_N, G = 121.102, 24.105, 9.8
L_X, HEIGHT, X0 = 1.0e-4, 1.0e-4, -2.5e-5
K = 2.0 * np.pi / L_X
ATWOOD = (RHO_S - RHO_N) / (RHO_S + RHO_N)
SIGMA = np.sqrt(ATWOOD * K * G)
LINEAR_SLOPE = 0.15
# (L_x / dr, hydrostatic start, displaced interface, further --set KEY=VALUE)
RUNS = {"rt-linear-n96": (96, False, False, ()), "rt-linear-n192": (192, False, False, ()),
        "rt-paper": None}
RUNS.update({f"rt-hydro-n{n}": (n, True, False, ()) for n in (96, 144, 192)})
RUNS.update({f"rt-mode-n{n}": (n, True, True, ()) for n in (96, 144, 192)})
RUNS["rt-linear-n96-pb0.05"] = (96, False, False, ("physics.background_pressure=0.05",))
RUNS.update({f"rt-mode-n96-pb{p}": (96, True, True, (f"physics.background_pressure={p}",))
             for p in ("0.05", "0.02")})
RUNS.update({f"rt-ka0.1-n{n}-pb{p}": (n, True, True, ("interface.amplitude=1.6e-6",
                                                      f"physics.background_pressure={p}"))
             for p in ("0", "0.02") for n in (96, 144, 192)})


def command(run):
    if run is None:
        return ["run", str(PAPER_CASE)]
    n, hydrostatic, displaced, sets = run
    dr = L_X / n
    return ["run", str(CASE), "--set", f"discretisation.dr={dr!r}",
            "--set", f"output.snapshot_every={max(1, round(80 * n / 96))}",
            "--set", f"initial.hydrostatic={'true' if hydrostatic else 'false'}",
            "--set", f"interface.perturbation={'displacement' if displaced else 'kinds'}",
            *[word for key in sets for word in ("--set", key)]]


def interface_amplitude(path):
    with h5py.File(path) as f:
        time = float(f.attrs["time"])
        superfluid = f["particles/superfluid/position"][...]
        normal = f["particles/normal/position"][...]
    edges = np.linspace(X0, X0 + L_X, 25)
    centres = 0.5 * (edges[1:] + edges[:-1])
    heights = []
    for left, right in zip(edges[:-1], edges[1:]):
        above = superfluid[(superfluid[:, 0] >= left) & (superfluid[:, 0] < right), 1]
        below = normal[(normal[:, 0] >= left) & (normal[:, 0] < right), 1]
        heights.append(0.5 * (above.min() + below.max()))
    heights = np.array(heights)
    return time, 2.0 * np.mean((heights - heights.mean()) * np.sin(K * centres))


def paper_figure(runs, out, report):
    paths = snapshots(runs / "rt-paper")
    shown = paths[1:][-4:] if len(paths) > 4 else paths
    fig, axes = plt.subplots(3, len(shown), figsize=(3.4 * len(shown), 16), squeeze=False)
    rows = []
    with h5py.File(shown[-1]) as f:
        speed_scale = np.percentile(np.concatenate([
            np.hypot(*(f[f"particles/{k}/momentum"][...] /
                       f[f"particles/{k}/mass"][...].reshape(-1, 1)).T)
            for k in ("superfluid", "normal")]), 99) * 1e3
        viscous_scale = np.percentile(np.linalg.norm(
            f["particles/normal/viscous_acceleration"][...], axis=1), 99)
    for column, path in enumerate(shown):
        with h5py.File(path) as f:
            time = float(f.attrs["time"])
            kinds = {k: (f[f"particles/{k}/position"][...], f[f"particles/{k}/momentum"][...] /
                         f[f"particles/{k}/mass"][...].reshape(-1, 1),
                         np.linalg.norm(f[f"particles/{k}/viscous_acceleration"][...], axis=1))
                     for k in ("superfluid", "normal")}
        scaled = time * np.sqrt(G / L_X)
        for kind, colour in (("superfluid", "tab:red"), ("normal", "tab:blue")):
            x = kinds[kind][0]
            axes[0, column].scatter(x[:, 0] * 1e6, x[:, 1] * 1e6, s=0.3, c=colour, lw=0)
        x = np.concatenate([kinds[k][0] for k in kinds])
        speed = np.concatenate([np.hypot(*kinds[k][1].T) for k in kinds]) * 1e3
        viscous = np.concatenate([kinds[k][2] for k in kinds])
        viscous_image = axes[1, column].scatter(x[:, 0] * 1e6, x[:, 1] * 1e6, s=0.3, c=viscous,
                                                cmap="magma", vmin=0, vmax=viscous_scale, lw=0)
        image = axes[2, column].scatter(x[:, 0] * 1e6, x[:, 1] * 1e6, s=0.3, c=speed,
                                        cmap="viridis", vmin=0, vmax=speed_scale, lw=0)
        for row in (0, 1, 2):
            axes[row, column].set(aspect="equal", xlim=(0, 100), ylim=(0, 200), xlabel="x (um)",
                                  title=f"t = {time * 1e3:.2f} ms\nt sqrt(g/L_x) = {scaled:.2f}")
        spike = kinds["superfluid"][0][:, 1].min()
        bubble = kinds["normal"][0][:, 1].max()
        rows.append((time, scaled, spike, bubble, kinds["superfluid"][2].max(),
                     np.median(kinds["normal"][2]), kinds["normal"][2].max()))
    fig.colorbar(viscous_image, ax=axes[1, -1], label="|eq. (34)'s term| (m/s^2)", shrink=0.8)
    fig.colorbar(image, ax=axes[2, -1], label="|v| (mm/s)", shrink=0.8)
    axes[0, 0].set(ylabel="(a) y (um): superfluid red, normal blue")
    axes[1, 0].set(ylabel="(b) y (um): viscosity term")
    axes[2, 0].set(ylabel="(c) y (um): speed")
    save_figure(fig, out / "two_fluid_rayleigh_taylor.png")
    with open(out / "two_fluid_rayleigh_taylor.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["time", "scaled_time", "lowest_superfluid_y", "highest_normal_y",
                         "superfluid_viscous_max", "normal_viscous_median", "normal_viscous_max"])
        writer.writerows([f"{v:.8g}" for v in r] for r in rows)
    t, scaled, spike, bubble, superfluid_viscous, normal_median, normal_max = rows[-1]
    report.append((f"rt-paper at t = {t * 1e3:.2f} ms (t sqrt(g/L_x) = {scaled:.2f}): the "
                   "superfluid spike's tip and the normal bubble's top (um)",
                   f"{spike * 1e6:.1f}, {bubble * 1e6:.1f}"))
    report.append(("rt-paper at the last snapshot: magnitude of eq. (34)'s viscosity term (m/s^2): largest on "
                   "a superfluid particle; median and largest on a normal particle",
                   f"{superfluid_viscous:.3g}; {normal_median:.3g}, {normal_max:.3g}"))


def make_figures(runs, out, report, names):
    if "rt-paper" in names:
        paper_figure(runs, out, report)
        names = [n for n in names if n != "rt-paper"]
    if not names:
        return
    fig, axis = plt.subplots(figsize=(7, 4.5))
    rows = []
    for name in names:
        series = np.array([interface_amplitude(p) for p in snapshots(runs / name)])
        t, a = series[:, 0], series[:, 1]
        linear = np.abs(a) * K < LINEAR_SLOPE
        (a0, sigma), _ = curve_fit(lambda s, a0, rate: a0 * np.cosh(rate * s), t[linear],
                                   a[linear], p0=[a[0], SIGMA])
        rows += [(name, ti, ai) for ti, ai in zip(t, a)]
        line = axis.plot(t * 1e3, np.abs(a) * 1e6, "o", ms=3, label=f"{name}")
        axis.plot(t[linear] * 1e3, np.abs(a0 * np.cosh(sigma * t[linear])) * 1e6, "-",
                  color=line[0].get_color(), label=f"fit: sigma = {sigma:.0f} 1/s")
        axis.plot(t * 1e3, np.abs(a0 * np.cosh(SIGMA * t)) * 1e6, ":", color="k")
        report.append((f"{name}: sigma from a0 cosh(sigma t) while k abs(a) < {LINEAR_SLOPE} "
                       f"({int(linear.sum())} snapshots, to t = {t[linear].max() * 1e3:.2f} ms)",
                       f"{sigma:.1f} 1/s, {100 * (sigma / SIGMA - 1):+.1f} % against "
                       f"sqrt(A k g) = {SIGMA:.1f}"))
    axis.plot([], [], ":", color="k", label=f"a0 cosh(sqrt(A k g) t), sqrt(A k g) = {SIGMA:.0f} 1/s")
    axis.axhline(LINEAR_SLOPE / K * 1e6, color="grey", lw=0.8, ls="--", label="k a = 0.15")
    axis.set(yscale="log", xlabel="t (ms)", ylabel="interface amplitude |a| (um)",
             title=f"Rayleigh-Taylor, couplings off: A = {ATWOOD:.3f}, k = 2 pi / L_x")
    axis.legend(fontsize=7)
    fig.tight_layout()
    save_figure(fig, out / "two_fluid_rayleigh_taylor_growth.png")
    with open(out / "two_fluid_rayleigh_taylor_growth.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["run", "time", "amplitude"])
        writer.writerows([r[0], f"{r[1]:.8g}", f"{r[2]:.8g}"] for r in rows)


def main():
    return chosen_runs_main(__doc__, "out/two_fluid", RUNS, lambda name: command(RUNS[name]),
                            make_figures, "two_fluid_rayleigh_taylor.md")


if __name__ == "__main__":
    sys.exit(main())
