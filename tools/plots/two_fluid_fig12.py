"""Paper 5's Fig. 12: the histogram of the pore areas of the normal fluid's vortices in the rotating
cylinder (sec. V.3) at t = 5 s. The paper measured them with ImageJ on its particle image (areas
in pixel^2) and reads the histogram's breadth as the distance from a quantum vortex lattice (all
pores alike: a delta function).

Usage: /usr/bin/python3 tools/plots/two_fluid_fig12.py [--make-runs] [--runs DIR] [--out DIR]
           [--revsph PATH] [--threads N]

--make-runs runs, into RUNS/NAME (default RUNS = out/two_fluid),
models/two_fluid/cases/rotating-cylinder.toml (160 particles across) to 5 s with the first and the
last snapshot only, 6-10 minutes each on two threads:
  cylinder-fig12        C_omega = 0.01, the case's (the paper's, sec. V.3)
  cylinder-fig12-c0.05  C_omega = 0.05, where the C_omega scan (README) finds the normal fluid's
                        vortices growing
Writes OUT/two_fluid_fig12.png (default OUT = docs/figures/two_fluid_fig12: per run the image the
pores are found in and the histograms at t = 0 and 5 s), OUT/two_fluid_fig12.csv (the histograms)
and OUT/two_fluid_fig12.md (count, mean, median and spread of the areas, of all pores and of
those of 10 dr^2 or more: a vortex's core rather than a stray particle).

The image stands in for the paper's picture of the particles: pixels of dr / 2 inside the
cylinder, each of the kind of its nearest fluid particle (a Voronoi picture of the particles, the
wall excluded). A pore is a connected region (4-neighbour) of normal-fluid pixels, as ImageJ's
"Analyze Particles" finds them on a thresholded picture; its area is given in dr^2 (4 pixels).
The start (t = 0, the normal particles drawn at random among the superfluid ones) is the
reference: a random mixture's clusters have a broad histogram of their own, so "broad" is judged
against it, not against a delta function alone.
"""

import sys
from pathlib import Path

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy import ndimage  # noqa: E402
from scipy.spatial import cKDTree  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from revsph_runs import REPO, run_rows_main, snapshots  # noqa: E402

RUNS = {"cylinder-fig12": 0.01, "cylinder-fig12-c0.05": 0.05}
RADIUS = 1.0e-3
DR = 1.25e-5  # the case's spacing
PIXEL = 0.5 * DR
# Pore areas in dr^2, a particle's Voronoi cell about 1: bins centred on whole particles.
BINS = np.array([0.5, 1.5, 2.5, 3.5, 5.5, 8.5, 13.5, 20.5, 32.5, 50.5, 80.5, 128.5, 200.5, 400.5])
# Pores of this area (dr^2) and more: a vortex's core, not a stray particle or two (ImageJ's
# "Analyze Particles" is given such a size floor).
LARGE = 10


def command(c_omega):
    return ["run", str(REPO / "models" / "two_fluid" / "cases" / "rotating-cylinder.toml"),
            "--t-end", "5.0", "--set", "output.snapshot_every=0",
            "--set", f"spin.coefficient={c_omega!r}"]


def kind_image(path):
    """Time and the picture: True where the nearest fluid particle of the pixel is normal, False
    where superfluid, inside the cylinder; the mask of the pixels inside."""
    with h5py.File(path) as f:
        time = float(f.attrs["time"])
        x_n = f["particles/normal/position"][...]
        x_s = f["particles/superfluid/position"][...]
    everyone = np.concatenate([x_n, x_s])
    centres = (np.arange(int(2 * RADIUS / PIXEL)) + 0.5) * PIXEL - RADIUS
    px, py = np.meshgrid(centres, centres, indexing="ij")
    inside = np.hypot(px, py) < RADIUS
    _, nearest = cKDTree(everyone).query(np.column_stack([px[inside], py[inside]]))
    normal = np.zeros(px.shape, dtype=bool)
    normal[inside] = nearest < len(x_n)
    return time, normal, inside


def pore_areas(normal):
    """The areas (dr^2) of the connected normal regions of the picture."""
    labels, count = ndimage.label(normal)
    pixels = np.bincount(labels.ravel(), minlength=count + 1)[1:]
    return pixels * (PIXEL / DR) ** 2


def describe(areas):
    large = areas[areas >= LARGE]
    text = (f"{len(areas)} pores; mean {areas.mean():.2f}, median {np.median(areas):.2f}, "
            f"std / mean {areas.std() / areas.mean():.2f}, largest {areas.max():.1f}; "
            f"{100 * large.sum() / areas.sum():.1f} % of the normal area in {len(large)} pores "
            f">= {LARGE} dr^2")
    if len(large) > 1:
        text += (f", their mean {large.mean():.1f}, median {np.median(large):.1f}, std / mean "
                 f"{large.std() / large.mean():.2f}")
    return text


def draw_run(fig, axes, run, c_omega, columns, report):
    name = run.name
    tag = f"C_omega = {c_omega:g}"
    image_axis, histogram_axis = axes
    centres = np.sqrt(BINS[1:] * BINS[:-1])
    columns["area_bin_low_dr2"] = BINS[:-1]
    columns["area_bin_high_dr2"] = BINS[1:]
    for which, style in ((0, ":"), (-1, "-")):
        time, normal, inside = kind_image(snapshots(run)[which])
        areas = pore_areas(normal)
        counts, _ = np.histogram(areas, BINS)
        columns[f"{name}_t{time:.2f}_count"] = counts
        histogram_axis.step(centres, counts, where="mid", ls=style, label=f"t = {time:.2f} s")
        report.append((f"{name} ({tag}), t = {time:.3f} s: pore areas (dr^2)", describe(areas)))
    shown = np.where(inside, normal.astype(float), np.nan)
    image_axis.imshow(shown.T, origin="lower", cmap="coolwarm_r", interpolation="nearest",
                      extent=[-RADIUS * 1e3, RADIUS * 1e3, -RADIUS * 1e3, RADIUS * 1e3])
    image_axis.set(title=f"normal (blue) and superfluid (red) pixels\nt = {time:.2f} s, {tag}",
                   xlabel="x (mm)", ylabel="y (mm)", aspect="equal")
    histogram_axis.set(xscale="log", yscale="log", xlabel="pore area (dr^2; 1 dr^2 = 4 pixels)",
                       ylabel="number of pores", title=f"pore areas, {tag}")
    histogram_axis.legend()


def main():
    return run_rows_main(__doc__, "out/two_fluid", "two_fluid_fig12", RUNS, command, draw_run,
                         panels=2, panel_width=5.5)


if __name__ == "__main__":
    sys.exit(main())
