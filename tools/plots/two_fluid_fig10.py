"""Paper 5's Fig. 10: the rotating cylinder (sec. V.3) at t = 0.5 s: (a) the superfluid particles
in red and the normal ones in blue, (b) every particle coloured by its speed, (c) the centre of
(b) coloured by the magnitude of eq. (40)'s spin force (the `spin_force` output view).

Usage: /usr/bin/python3 tools/plots/two_fluid_fig10.py [--make-runs] [--runs DIR] [--out DIR]
           [--revsph PATH] [--threads N]

--make-runs runs, into RUNS/NAME (default RUNS = out/two_fluid),
models/two_fluid/cases/rotating-cylinder.toml (160 particles across) to 0.5 s, about a minute
each on one thread:
  cylinder-fig10        C_omega = 0.01, the case's (the paper's "C_omega = 0.01" of sec. V.3)
  cylinder-fig10-c0.05  C_omega = 0.05, in the regime where the C_omega scan (README) finds the
                        normal fluid's vortices growing
Writes OUT/two_fluid_fig10.png (default OUT = docs/figures/two_fluid_fig10; one row per run),
OUT/two_fluid_fig10.csv (per run, ring means over 20 rings of the speed of each kind and of the
normal particles' spin force) and OUT/two_fluid_fig10.md (the numbers, with how much the normal
particles gather among themselves: 1 for a random mixture).
"""

import sys
from pathlib import Path

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.spatial import cKDTree  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from revsph_runs import REPO, run_rows_main, snapshots  # noqa: E402

RUNS = {"cylinder-fig10": 0.01, "cylinder-fig10-c0.05": 0.05}
RADIUS = 1.0e-3
DR = 1.25e-5  # the case's spacing
RINGS = 20
KINDS = {"superfluid": "tab:red", "normal": "tab:blue"}


def command(c_omega):
    return ["run", str(REPO / "models" / "two_fluid" / "cases" / "rotating-cylinder.toml"),
            "--t-end", "0.5", "--set", "output.snapshot_every=0",
            "--set", f"spin.coefficient={c_omega!r}"]


def read_final(run, which=-1):
    """Time and, per fluid kind: positions, speeds and the spin force's magnitude (zeros when the
    snapshot has no spin_force view), of the run's last snapshot (or `which`)."""
    path = snapshots(run)[which]
    kinds = {}
    with h5py.File(path) as f:
        for kind in KINDS:
            g = f[f"particles/{kind}"]
            x = g["position"][...]
            v = g["velocity"][...] if "velocity" in g else \
                g["momentum"][...] / g["mass"][...].reshape(-1, 1)
            force = g["spin_force"][...] if "spin_force" in g else np.zeros_like(x)
            kinds[kind] = (x, np.linalg.norm(v, axis=1), np.linalg.norm(force, axis=1))
        return float(f.attrs["time"]), kinds


def clustering(kinds):
    """How much the normal particles keep to their own kind: the share of normal particles among
    each normal particle's neighbours within 1.5 dr (itself excluded), averaged, over the normal
    share of all fluid particles. 1 for a random mixture, above 1 where they gather (Fig. 10's
    vortices)."""
    x_s, x_n = kinds["superfluid"][0], kinds["normal"][0]
    everyone = np.concatenate([x_n, x_s])
    normal = np.arange(len(everyone)) < len(x_n)
    tree = cKDTree(everyone)
    shares = []
    for i, neighbours in enumerate(tree.query_ball_point(x_n, 1.5 * DR)):
        others = [j for j in neighbours if j != i]
        if others:
            shares.append(np.mean(normal[others]))
    return float(np.mean(shares) / normal.mean())


def ring_means(r, values):
    edges = np.linspace(0.0, RADIUS, RINGS + 1)
    index = np.clip(np.digitize(r, edges) - 1, 0, RINGS - 1)
    means = np.array([values[index == k].mean() if np.any(index == k) else np.nan
                      for k in range(RINGS)])
    spread = np.array([values[index == k].std() if np.any(index == k) else np.nan
                       for k in range(RINGS)])
    return 0.5 * (edges[1:] + edges[:-1]), means, spread


def draw_row(fig, axes, run, c_omega, columns, report):
    time, kinds = read_final(run)
    (a, b, c) = axes
    tag = f"C_omega = {c_omega:g}"
    for kind, colour in KINDS.items():
        x = kinds[kind][0]
        a.scatter(x[:, 0] * 1e3, x[:, 1] * 1e3, s=0.3, c=colour, label=kind, rasterized=True)
    a.set_title(f"(a) kinds, t = {time:.3f} s, {tag}")
    a.legend(loc="upper right", markerscale=10)
    x_all = np.concatenate([kinds[k][0] for k in KINDS])
    speed_all = np.concatenate([kinds[k][1] for k in KINDS])
    shown = b.scatter(x_all[:, 0] * 1e3, x_all[:, 1] * 1e3, s=0.3, c=speed_all * 1e3,
                      cmap="viridis", rasterized=True)
    fig.colorbar(shown, ax=b, label="|v| (mm/s)")
    b.set_title(f"(b) speed, {tag}")
    x_n, _, force_n = kinds["normal"]
    centre = np.linalg.norm(x_n, axis=1) < 0.25 * RADIUS
    shown = c.scatter(x_n[centre, 0] * 1e3, x_n[centre, 1] * 1e3, s=4, c=force_n[centre],
                      cmap="magma", rasterized=True)
    fig.colorbar(shown, ax=c, label="|F_spin| of eq. (40) (N/m)")
    c.set_title(f"(c) centre: normal |F_spin|, {tag}")
    for axis in axes:
        axis.set_aspect("equal")
        axis.set_xlabel("x (mm)")
        axis.set_ylabel("y (mm)")
    name = run.name
    for kind in KINDS:
        x, speed, force = kinds[kind]
        r = np.linalg.norm(x, axis=1)
        mid, mean, spread = ring_means(r, speed)
        columns["r_m"] = mid
        columns[f"{name}_{kind}_speed_mean"] = mean
        columns[f"{name}_{kind}_speed_std"] = spread
        if kind == "normal":
            columns[f"{name}_normal_spin_force_mean"] = ring_means(r, force)[1]
        inner = r < 0.6 * RADIUS
        report.append((f"{name}: {kind}: particles", str(len(speed))))
        report.append((f"{name}: {kind}: speed mean / std at r < 0.6 R (mm/s)",
                       f"{1e3 * speed[inner].mean():.4g} / {1e3 * speed[inner].std():.4g}"))
    report.append((f"{name}: time of the snapshot (s)", f"{time:.4f}"))
    report.append((f"{name}: normal particles' clustering (1: random mixture), t = 0 and now",
                   f"{clustering(read_final(run, 0)[1]):.3f}, {clustering(kinds):.3f}"))
    report.append((f"{name}: normal: largest / mean spin force magnitude (N/m)",
                   f"{force_n.max():.3e} / {force_n.mean():.3e}"))


def main():
    return run_rows_main(__doc__, "out/two_fluid", "two_fluid_fig10", RUNS, command, draw_row,
                         panels=3)


if __name__ == "__main__":
    sys.exit(main())
