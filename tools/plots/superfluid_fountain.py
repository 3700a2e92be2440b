#!/usr/bin/python3
"""The superfluid fountain effect (paper 3 sec. III.C, Figs. 8-12): the jet speed against eq. (31)
at 60 and 80 W/m and two resolutions, the temperature and pressure fields, the cell's
temperature in time, and the relative jet speed against the Reynolds number (eq. 33).

Usage: /usr/bin/python3 tools/plots/superfluid_fountain.py [--make-runs] [--runs DIR] [--out DIR]
           [--revsph PATH] [--threads N] [--only NAME ...]

--make-runs writes each run's case with tools/plots/superfluid_fountain_case.py (dr = d / N,
the kernel's support 2.8 dr unless the run says otherwise, the authors' boundaries: the
absorbing cooler and no-slip glass)
into RUNS/cases and runs it into RUNS/NAME (default RUNS = out/superfluid), snapshots every
2.5 ms; a run that stopped early (a session's end) is continued from its last snapshot into
RUNS/NAME-2, NAME-3, ... (`revsph run --from`), so repeating the command chains it to the end.
The runs (viscosity mu; Re = W / (T0 s0 mu), eq. 33):
  fountain-n4-w60, -w80, -w100               N = 4, mu = 1e-4 (Table I)
  fountain-n6-w60, fountain-n6-w80          N = 6
  fountain-n8-w80                           N = 8
  fountain-n4-w80-2h                        N = 4, support 5.6 dr (eq. 17 as printed: 2h)
  fountain-n4-w80-conducting                N = 4, the boundaries of issue 17: a conducting
                                            cooler, free-slip glass
  fountain-n4-w80-glass                     N = 4, no-slip glass alone (conducting cooler)
  fountain-n4-w80-cooler                    N = 4, the absorbing cooler alone (free-slip glass)
  fountain-n4-w80-mu3e-4, -mu1e-3           N = 4, Re about 480 and 145 (Fig. 11)
  fountain-n4-w80-start                     N = 4, to t = 1 ms, snapshots every 0.25 ms (Fig. 10)
Writes into --out (default docs/figures):
  superfluid_fountain_jet.png   jet speed in time against eq. (31) (Fig. 8)
  superfluid_fountain_fields.png coflow speed and pressure at the end (Fig. 9)
  superfluid_fountain_start.png temperature in the cell in the first millisecond (Fig. 10)
  superfluid_fountain_re.png    the cell's temperature in time; v_jet / v_ideal against Re (Fig. 11)
  superfluid_fountain_frames.png temperature and the fountain's shape every 37.5 ms (Fig. 12)
  superfluid_fountain.csv       per run: N, W, mu, Re, mean jet speed over t > 0.2 s, eq. (31)
  superfluid_fountain_jet.csv   per run and snapshot interval: t, jet speed, eq. (31), cell T
  superfluid_fountain.md        the numbers (also printed)

The jet speed is the net volume (m / rho) of the particles crossing y = 33.7 mm within the
capillary's mouth (|x| < 2.3 mm, its walls included) between snapshots, over the interval and the
capillary's width d = 1.55 mm; eq. (31) uses the mean T, s and rho of the cell (|x| < 8 mm,
3 mm < y < 16.7 mm, above the superleak) and the heater's power at that time (its ramp).
"""

import subprocess
import sys
from pathlib import Path

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from revsph_runs import REPO, chosen_runs, figure_parser, find_revsph, save_figure, write_report  # noqa: E402

D_CAPILLARY = 1.55e-3
JET_HEIGHT = 33.7e-3
MOUTH_HALF_WIDTH = 2.3e-3
CELL = ((-8e-3, 8e-3), (3e-3, 16.7e-3))
BELOW = ((-8e-3, 8e-3), (-10e-3, -3e-3))  # the bath under the cell, below the superleak
CAPILLARY = ((-1.2e-3, 1.2e-3), (16.7e-3, JET_HEIGHT))
MOUTH = ((-1.2e-3, 1.2e-3), (JET_HEIGHT - 3e-3, JET_HEIGHT))  # the capillary's last 3 mm
HEAT_CAPACITY = 1861.0  # C of Table I (J/(kg K)): ds = C dT / T
CHI_N0, CHI_SLOPE = 0.1934, 5.851e-4  # chi_n = chi_n0 + chi' (s - s0), eq. (8), Table I
SUPERLEAK_PLANE = 1e-3                # the superleak's mid-plane (y)
T0, S0, RHO0 = 1.65, 335.0, 145.2
RAMP = 0.02
AVERAGE_FROM = 0.2
SUPPORT = 2.8  # the kernel's support in dr: Table I's h, as the authors' code uses it
RUNS = {
    "fountain-n4-w60": dict(n=4, power=60.0, mu=1e-4),
    "fountain-n4-w80": dict(n=4, power=80.0, mu=1e-4),
    "fountain-n4-w100": dict(n=4, power=100.0, mu=1e-4),
    "fountain-n6-w60": dict(n=6, power=60.0, mu=1e-4),
    "fountain-n6-w80": dict(n=6, power=80.0, mu=1e-4),
    "fountain-n8-w80": dict(n=8, power=80.0, mu=1e-4),
    "fountain-n4-w80-2h": dict(n=4, power=80.0, mu=1e-4, support=5.6),
    "fountain-n4-w80-conducting": dict(n=4, power=80.0, mu=1e-4, sets=[
        "physics.cooler=conducting", "physics.dummy_slip=free"]),
    "fountain-n4-w80-glass": dict(n=4, power=80.0, mu=1e-4, sets=["physics.cooler=conducting"]),
    "fountain-n4-w80-cooler": dict(n=4, power=80.0, mu=1e-4, sets=["physics.dummy_slip=free"]),
    "fountain-n4-w80-mu3e-4": dict(n=4, power=80.0, mu=3e-4),
    "fountain-n4-w80-mu1e-3": dict(n=4, power=80.0, mu=1e-3),
    "fountain-n4-w80-start": dict(n=4, power=80.0, mu=1e-4, t_end=1e-3, every=2.5e-4),
}


def reynolds(run):
    return run["power"] / (T0 * S0 * run["mu"])  # eq. (33)


def support_of(run):
    return run.get("support", SUPPORT)


def time_step(n):
    return 0.2 * 2.8 * (D_CAPILLARY / n) / 40.0  # dt = h / (5 u1), h = 2.8 dr (Table I)


def segments(runs, name):
    """The run's directories in order: NAME, NAME-2, NAME-3, ..."""
    found = [runs / name] if (runs / name).is_dir() else []
    k = 2
    while (runs / f"{name}-{k}").is_dir():
        found.append(runs / f"{name}-{k}")
        k += 1
    return found


def snapshot_files(runs, name):
    """Every snapshot of the run over its segments, one per step, in step order."""
    by_step = {}
    for directory in segments(runs, name):
        for path in sorted((directory / "snapshots").glob("step_*.h5")):
            by_step[int(path.stem.split("_")[1])] = path
    return [by_step[s] for s in sorted(by_step)]


def snapshot_time(path):
    with h5py.File(path) as f:
        return float(f.attrs["time"])


def make_run(runs, name, revsph, threads):
    """Starts the run, or continues it from its last snapshot if it stopped before its end."""
    run = RUNS[name]
    t_end = run.get("t_end", 0.3)
    every = max(1, round(run.get("every", 2.5e-3) / time_step(run["n"])))
    files = snapshot_files(runs, name)
    if files and snapshot_time(files[-1]) >= t_end - 0.5 * time_step(run["n"]):
        return
    if files:
        out = runs / f"{name}-{len(segments(runs, name)) + 1}"
        command = [str(revsph), "run", "--from", str(files[-1])]
    else:
        cases = runs / "cases"
        subprocess.run([sys.executable, str(Path(__file__).with_name("superfluid_fountain_case.py")),
                        str(run["n"]), name, repr(run["power"]), "--support",
                        repr(support_of(run)), "--out", str(cases)], check=True)
        out = runs / name
        command = [str(revsph), "run", str(cases / f"{name}.toml"),
                   "--set", f"physics.viscosity={run['mu']!r}",
                   "--set", f"output.snapshot_every={every}"]
        for setting in run.get("sets", []):
            command += ["--set", setting]
    command += ["--t-end", repr(t_end), "--out", str(out), "--force"]
    if threads:
        command += ["--threads", threads]
    print("+", " ".join(command), flush=True)
    subprocess.run(command, check=True)


def read_snapshot(path):
    with h5py.File(path) as f:
        fluid = f["particles/fluid"]
        data = {key: fluid[key][...] for key in
                ("position", "mass", "density", "temperature", "mean_entropy", "pressure",
                 "mean_velocity", "normal_velocity", "mean_superflow_velocity")}
        data["time"] = float(f.attrs["time"])
        data["solid"] = np.concatenate([f[f"particles/{kind}/position"][...]
                                        for kind in ("dummy", "wall")])
    return data


def in_box(x, box):
    (x0, x1), (y0, y1) = box
    return (x[:, 0] > x0) & (x[:, 0] < x1) & (x[:, 1] > y0) & (x[:, 1] < y1)


def series(runs, name):
    """Per snapshot: time t, the cell's mean T, the mean T under the superleak (below), eq. (31)
    (ideal); per interval: the volume crossed at the capillary's mouth (crossed)."""
    run = RUNS[name]
    times, temperature, below, ideal, crossed, cell_mass = [], [], [], [], [], []
    mouth_v, mouth_vn = [], []
    previous = None
    for path in snapshot_files(runs, name):
        s = read_snapshot(path)
        cell = in_box(s["position"], CELL)
        under = in_box(s["position"], BELOW)
        below.append(np.average(s["temperature"][under], weights=s["mass"][under]))
        weight = s["mass"][cell]
        cell_mass.append(weight.sum() + s["mass"][in_box(s["position"], CAPILLARY)].sum())
        mouth = in_box(s["position"], MOUTH)
        mouth_v.append(np.sum(s["mean_velocity"][mouth, 1]))
        mouth_vn.append(np.sum(s["normal_velocity"][mouth, 1]))
        mean = {k: np.average(s[k][cell], weights=weight)
                for k in ("temperature", "mean_entropy", "density")}
        power = run["power"] * min(s["time"] / RAMP, 1.0)
        times.append(s["time"])
        temperature.append(mean["temperature"])
        # Eq. (31): v = W / (T s rho d).
        ideal.append(power / (mean["temperature"] * mean["mean_entropy"] * mean["density"]
                              * D_CAPILLARY))
        if previous is not None:
            y0, y1 = previous["position"][:, 1], s["position"][:, 1]
            up = (y0 < JET_HEIGHT) & (y1 >= JET_HEIGHT) & (
                np.abs(previous["position"][:, 0]) < MOUTH_HALF_WIDTH)
            down = (y0 >= JET_HEIGHT) & (y1 < JET_HEIGHT) & (
                np.abs(s["position"][:, 0]) < MOUTH_HALF_WIDTH)
            volume = s["mass"] / s["density"]
            crossed.append(volume[up].sum() - volume[down].sum())
        previous = s
    return {"t": np.array(times), "temperature": np.array(temperature),
            "below": np.array(below), "ideal": np.array(ideal), "crossed": np.array(crossed),
            "cell_mass": np.array(cell_mass), "mouth_v": np.array(mouth_v),
            "mouth_vn": np.array(mouth_vn)}


def pair_entropy_flux(s, plane, support):
    """The entropy per second the reversible pair term of eq. (19) carries up through y = plane
    (|x| < 8.5 mm) at a snapshot: -sum m_a m_b (w'/r) (J_a + J_b) . x_ab over the pairs with a
    above and b below, J = s (chi_s / chi_n) (v - v_s) / rho, the model's Wendland kernel."""
    x = s["position"]
    near = np.where((np.abs(x[:, 0]) < 8.5e-3) & (np.abs(x[:, 1] - plane) < support))[0]
    above = near[x[near, 1] >= plane]
    below = near[x[near, 1] < plane]
    chi_n = CHI_N0 + CHI_SLOPE * (s["mean_entropy"] - S0)
    flux = (s["mean_entropy"] * (1.0 - chi_n) / (chi_n * s["density"]))[:, None] * (
        s["mean_velocity"] - s["mean_superflow_velocity"])
    x_ab = x[above][:, None, :] - x[below][None, :, :]
    q = np.minimum(np.linalg.norm(x_ab, axis=2) / support, 1.0)
    # w = 7 / (pi H^2) (1 - q)^4 (1 + 4 q), H the support: w'/r = -140 (1 - q)^3 / (pi H^4).
    slope = -140.0 * (1.0 - q) ** 3 / (np.pi * support**4)
    j_sum = flux[above][:, None, :] + flux[below][None, :, :]
    m_ab = s["mass"][above][:, None] * s["mass"][below][None, :]
    return -np.sum(m_ab * slope * np.sum(j_sum * x_ab, axis=2))


def superleak_balance(runs, name):
    """The entropy through the superleak's mid-plane over t > 0.2 s, per second: by the pair term
    (mean over the snapshots) and by the particles crossing it (between snapshots)."""
    support = support_of(RUNS[name]) * D_CAPILLARY / RUNS[name]["n"]
    pair, carried, duration = [], 0.0, 0.0
    previous = None
    for path in snapshot_files(runs, name):
        if snapshot_time(path) < AVERAGE_FROM - 1e-9:
            continue
        s = read_snapshot(path)
        pair.append(pair_entropy_flux(s, SUPERLEAK_PLANE, support))
        if previous is not None:
            y0, y1 = previous["position"][:, 1], s["position"][:, 1]
            inside = np.abs(s["position"][:, 0]) < 8.5e-3
            up = (y0 < SUPERLEAK_PLANE) & (y1 >= SUPERLEAK_PLANE) & inside
            down = (y0 >= SUPERLEAK_PLANE) & (y1 < SUPERLEAK_PLANE) & inside
            ms = s["mass"] * s["mean_entropy"]
            carried += ms[up].sum() - ms[down].sum()
            duration += s["time"] - previous["time"]
        previous = s
    return np.mean(pair), carried / duration


def jet_summary(runs, name):
    data = series(runs, name)
    t, ideal, crossed = data["t"], data["ideal"], data["crossed"]
    late = t[:-1] >= AVERAGE_FROM - 1e-9  # intervals starting at or after 0.2 s
    span = t[1:][late][-1] - t[:-1][late][0]
    mean_jet = crossed[late].sum() / (span * D_CAPILLARY)
    # Eq. (31) averaged over the same intervals (trapezoid on the snapshots).
    mid_ideal = 0.5 * (ideal[:-1] + ideal[1:])
    mean_ideal = np.sum(mid_ideal[late] * np.diff(t)[late]) / span
    # The temperature jump at the superleak, cell minus below, averaged over the same snapshots.
    after = t >= AVERAGE_FROM - 1e-9
    jump = np.mean((data["temperature"] - data["below"])[after])
    # The heat the cell keeps: its mass (with the capillary's) times C dT/dt, dT/dt the
    # least-squares slope of its mean T over the same snapshots, as a fraction of the power:
    # what eq. (31), a steady state, leaves out.
    slope = np.polyfit(t[after], data["temperature"][after], 1)[0]
    stored = np.mean(data["cell_mass"][after]) * HEAT_CAPACITY * slope / RUNS[name]["power"]
    # The entropy leaves with the normal fluid (flux rho s v_n): v_n / v in the capillary's last
    # 3 mm above 1 is a counterflow that carries heat out with less mass.
    counterflow = np.sum(data["mouth_vn"][after]) / np.sum(data["mouth_v"][after])
    return data, mean_jet, mean_ideal, jump, stored, counterflow


def moving_jet(t, crossed, window):
    """Jet speed over windows of `window` snapshot intervals, at their centres."""
    k = max(1, window)
    volume = np.convolve(crossed, np.ones(k), mode="valid")
    duration = t[k:] - t[:-k]
    centre = 0.5 * (t[k:] + t[:-k])
    return centre, volume / (duration * D_CAPILLARY)


def scatter_field(ax, s, values, label, cmap, vmin=None, vmax=None, region=None, size=0.6):
    ax.scatter(s["solid"][:, 0] * 1e3, s["solid"][:, 1] * 1e3, s=size / 2, c="0.75", lw=0)
    x = s["position"]
    keep = np.ones(len(x), bool) if region is None else region(x)
    image = ax.scatter(x[keep, 0] * 1e3, x[keep, 1] * 1e3, s=size, c=values[keep], cmap=cmap,
                       vmin=vmin, vmax=vmax, lw=0)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    plt.colorbar(image, ax=ax, label=label, shrink=0.8)
    return image


def fig_jet(runs, out, report, available):
    fig, axes = plt.subplots(1, 3, figsize=(18, 4.8), sharey=False)
    panel = {60.0: 0, 80.0: 1, 100.0: 2}
    rows, jet_rows = [], {k: [] for k in ("run", "t_start", "t_end", "v_jet", "v_ideal",
                                          "cell_temperature")}
    for name in available:
        run = RUNS[name]
        if "t_end" in run:
            continue
        if snapshot_time(snapshot_files(runs, name)[-1]) < AVERAGE_FROM + 0.02:
            report.append((f"{name}: not yet past t = {AVERAGE_FROM + 0.02} s", "skipped"))
            continue
        data, mean_jet, mean_ideal, jump, stored, counterflow = jet_summary(runs, name)
        # The heat balance of the cell, eq. (32) with what it keeps: W = (heat up the jet,
        # carried at v_n) + (kept) + (the rest: through the superleak and the walls).
        rest = 1.0 - stored - mean_jet * counterflow / mean_ideal
        t, temperature, ideal, crossed = (data[k] for k in ("t", "temperature", "ideal",
                                                              "crossed"))
        pair, carried = superleak_balance(runs, name)
        entropy_input = run["power"] / np.mean(temperature[t >= AVERAGE_FROM - 1e-9])
        deficit = 100.0 * (1.0 - mean_jet / mean_ideal)
        # Eq. (31) with the reference state instead of the cell's: W / (T0 s0 rho0 d), as the
        # authors' fountain_2d.jl prints it (v_theory).
        ideal_reference = run["power"] / (T0 * S0 * RHO0 * D_CAPILLARY)
        deficit_reference = 100.0 * (1.0 - mean_jet / ideal_reference)
        warming = 1e3 * (temperature[-1] - T0)
        rows.append((name, run["n"], support_of(run), run["power"], run["mu"], reynolds(run),
                     mean_jet, mean_ideal, deficit, ideal_reference, deficit_reference, warming,
                     1e3 * jump, 100.0 * stored, counterflow, 100.0 * rest, t[-1]))
        report.append((f"{name}: mean jet speed over t > {AVERAGE_FROM} s (m/s)",
                       f"{mean_jet:.4f} against eq. (31) {mean_ideal:.4f}: {deficit:.2f} % below "
                       f"(Re {reynolds(run):.0f}; paper at W = 60, 80: 1.95 %, 2.38 % below); "
                       f"against eq. (31) at T0, s0, rho0 {ideal_reference:.4f}: "
                       f"{deficit_reference:.2f} % below; the cell {warming:.1f} mK above T0 at "
                       f"t = {t[-1]:.3f} s; "
                       f"T jump at the superleak {1e3 * jump:.3f} mK; the cell keeps "
                       f"{100.0 * stored:.1f} % of the power; v_n / v at the mouth "
                       f"{counterflow:.3f}; the rest (superleak, walls) {100.0 * rest:.1f} %"))
        report.append((f"{name}: entropy up through the superleak's mid-plane, J/(K m s)",
                       f"pair term {pair:.2f}, particles {carried:.2f}, net {pair + carried:.2f} "
                       f"({100.0 * (pair + carried) / entropy_input:.1f} % of W / T)"))
        speed = crossed / (np.diff(t) * D_CAPILLARY)
        for i in range(len(crossed)):
            for key, value in zip(jet_rows, (name, t[i], t[i + 1], speed[i],
                                             0.5 * (ideal[i] + ideal[i + 1]), temperature[i + 1])):
                jet_rows[key].append(value)
        if run["mu"] != 1e-4 or run["power"] not in panel:
            continue
        ax = axes[panel[run["power"]]]
        centre, smooth = moving_jet(t, crossed, 8)
        line = ax.plot(centre, smooth, label=f"{name} (20 ms windows)")[0]
        ax.plot(t, ideal, "--", color=line.get_color(), lw=0.8, label=f"eq. (31), cell, {name}")
        ax.axhline(ideal_reference, color="k", ls=":", lw=0.8)
        ax.axvline(AVERAGE_FROM, color="0.6", lw=0.8)
        ax.set_title(f"W = {run['power']:.0f} W/m (dotted: eq. 31 at T0, s0, rho0)")
    for ax in axes:
        ax.set_xlabel("t (s)")
        ax.set_ylabel("jet speed (m/s)")
        ax.legend(fontsize=8)
    save_figure(fig, out / "superfluid_fountain_jet.png")
    columns = ("run", "N", "support_over_dr", "power_W_per_m", "viscosity", "Re",
               "mean_jet_speed", "eq31_speed", "deficit_percent", "eq31_speed_T0",
               "deficit_T0_percent", "cell_warming_mK", "superleak_jump_mK", "stored_percent",
               "mouth_vn_over_v", "rest_percent", "t_end")
    with open(out / "superfluid_fountain.csv", "w") as f:
        f.write(",".join(columns) + "\n")
        for row in rows:
            f.write(",".join(str(v) if isinstance(v, str) else f"{v:.6g}" for v in row) + "\n")
    names = jet_rows.pop("run")
    with open(out / "superfluid_fountain_jet.csv", "w") as f:
        f.write("run," + ",".join(jet_rows) + "\n")
        for i, name in enumerate(names):
            f.write(name + "," + ",".join(f"{jet_rows[k][i]:.8g}" for k in jet_rows) + "\n")
    return rows


def finest(available, power):
    candidates = [n for n in available if RUNS[n]["power"] == power and RUNS[n]["mu"] == 1e-4
                  and not {"t_end", "sets", "support"} & set(RUNS[n])]
    return max(candidates, key=lambda n: RUNS[n]["n"]) if candidates else None


def fig_fields(runs, out, report, available):
    names = [n for n in (finest(available, 60.0), finest(available, 80.0)) if n]
    if not names:
        return
    fig, axes = plt.subplots(2, len(names), figsize=(6 * len(names), 10), squeeze=False)
    for column, name in enumerate(names):
        s = read_snapshot(snapshot_files(runs, name)[-1])
        speed = np.linalg.norm(s["mean_velocity"], axis=1)
        scatter_field(axes[0, column], s, speed, "|v| (m/s)", "viridis", 0.0, 1.0)
        axes[0, column].set_title(f"{name}, t = {s['time']:.3f} s")
        scatter_field(axes[1, column], s, s["pressure"], "p (Pa)", "coolwarm", -300.0, 300.0)
        for ax in axes[:, column]:
            ax.set_ylim(-12, 70)
    save_figure(fig, out / "superfluid_fountain_fields.png")


def fig_start(runs, out, report, available):
    if "fountain-n4-w80-start" not in available:
        return
    files = snapshot_files(runs, "fountain-n4-w80-start")[1:5]
    fig, axes = plt.subplots(1, len(files), figsize=(4.2 * len(files), 4))
    for ax, path in zip(np.atleast_1d(axes), files):
        s = read_snapshot(path)
        scatter_field(ax, s, (s["temperature"] - T0) * 1e6, "T - T0 (uK)", "inferno",
                      region=lambda x: (np.abs(x[:, 0]) < 9e-3) & (x[:, 1] < 18e-3), size=12)
        ax.set_xlim(-9, 9)
        ax.set_ylim(-6, 18)
        ax.set_title(f"t = {s['time'] * 1e3:.2f} ms")
    save_figure(fig, out / "superfluid_fountain_start.png")


def fig_reynolds(runs, out, report, rows, available):
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.3))
    for name in available:
        run = RUNS[name]
        if run["power"] == 80.0 and run["mu"] == 1e-4 and "t_end" not in run:
            data = series(runs, name)
            line = axes[0].plot(data["t"], (data["temperature"] - T0) * 1e3,
                                label=f"cell, {name}")[0]
            axes[0].plot(data["t"], (data["below"] - T0) * 1e3, "--", color=line.get_color(),
                         label=f"under the superleak, {name}")
    axes[0].set_xlabel("t (s)")
    axes[0].set_ylabel("cell T - T0 (mK)")
    axes[0].set_title("W = 80 W/m")
    axes[0].legend(fontsize=7)
    scan = [r for r in rows
            if r[0] in ("fountain-n4-w80", "fountain-n4-w80-mu3e-4", "fountain-n4-w80-mu1e-3")]
    if scan:
        re = np.array([r[5] for r in scan])
        ratio = np.array([r[6] / r[7] for r in scan])
        axes[1].plot(re, ratio, "o-")
        for value, r in zip(re, ratio):
            report.append((f"v_jet / v_ideal at Re {value:.0f} (W = 80, dr = d/4)", f"{r:.4f}"))
    axes[1].set_xlabel("Re (eq. 33)")
    axes[1].set_ylabel("v_jet / v_ideal, t > 0.2 s")
    axes[1].set_title("W = 80 W/m, dr = d/4")
    save_figure(fig, out / "superfluid_fountain_re.png")


def fig_frames(runs, out, report, available):
    name = finest(available, 80.0)
    if not name:
        return
    files = snapshot_files(runs, name)
    times = np.array([snapshot_time(p) for p in files])
    wanted = [0.0375 * (k + 1) for k in range(8) if 0.0375 * (k + 1) <= times[-1] + 1e-9]
    frames = [read_snapshot(files[int(np.argmin(np.abs(times - t)))]) for t in wanted]
    if not frames:
        return
    top = max(np.max(s["temperature"]) for s in frames)
    fig, axes = plt.subplots(2, 4, figsize=(18, 11))
    for ax, s in zip(axes.flat, frames):
        scatter_field(ax, s, (s["temperature"] - T0) * 1e3, "T - T0 (mK)", "inferno", 0.0,
                      (top - T0) * 1e3, size=1.5)
        ax.set_ylim(-12, 60)
        ax.set_title(f"{name}, t = {s['time'] * 1e3:.1f} ms")
    for ax in list(axes.flat)[len(frames):]:
        ax.axis("off")
    save_figure(fig, out / "superfluid_fountain_frames.png")


def main():
    parser = figure_parser(__doc__, "out/superfluid", REPO / "docs" / "figures", RUNS)
    args = parser.parse_args()
    names = chosen_runs(parser, args, RUNS)
    runs, out = Path(args.runs), Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    if args.make_runs:
        revsph = find_revsph(args.revsph)
        for name in names:
            make_run(runs, name, revsph, args.threads)
    available = [n for n in RUNS if len(snapshot_files(runs, n)) >= 2]
    if not available:
        print(f"no fountain runs in {runs} (use --make-runs)")
        return 1
    report = []
    rows = fig_jet(runs, out, report, available)
    fig_fields(runs, out, report, available)
    fig_start(runs, out, report, available)
    fig_reynolds(runs, out, report, rows, available)
    fig_frames(runs, out, report, available)
    write_report(out / "superfluid_fountain.md", report)
    incomplete = [n for n in RUNS if n not in available]
    if incomplete:
        print("missing runs:", ", ".join(incomplete))
    return 0 if not incomplete else 1


if __name__ == "__main__":
    sys.exit(main())
