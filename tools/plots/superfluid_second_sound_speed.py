#!/usr/bin/python3
"""The simulated second-sound speed against u2 (paper 3 sec. III.B, eq. 25): the frequency of the
entropy at the probe (L/4, L/4) over the run, from the probe series that
tools/plots/superfluid_second_sound.py writes, and how much of eps1 (eq. 27) that phase lag alone
explains.

Usage: /usr/bin/python3 tools/plots/superfluid_second_sound_speed.py PROBE_CSV ... [--out CSV]
           [--errors CSV ...] [--wide NAME ...]

Each PROBE_CSV has the columns run, time, probe_entropy, eq25 (superfluid_second_sound_probe.csv).
Per cosine run, s(t) = c + a cos(w t + phi) is fitted by least squares to the probe's series
and to eq. (25)'s at the same times (a check of the fit: it must return u2), and the speed is
u = w L / (sqrt(2) pi) (the mode's |k| = sqrt(2) pi / L). Writes (--out, default
docs/figures/superfluid_second_sound_speed.csv): run, N, support_over_dr, u2 (eq. 25's fit),
the probe's speed, its relative difference, the phase behind eq. (25) at the end of the series
(rad), the amplitude ratio, and eps1 predicted by the fitted wave alone, 0.5 max_t
|(a / a25) cos(w t + phi) - cos(w25 t)| (0.5: the RMS of cos(pi x/L) cos(pi y/L) over the square)
over Table I's window t <= sqrt(2) L / u1 and over the whole series; with --errors (the
superfluid_second_sound.csv files holding these runs) also the measured eps1 in both windows;
and the probe's largest difference from eq. (25) over A s0 in both windows (Fig. 6). A run's
support is 6 dr when its name ends in -2h or --wide names it (the probe run of
docs/figures/superfluid_second_sound_n300/, made at 6 dr), else 3 dr.
"""

import csv
import re
import sys
from pathlib import Path

import numpy as np
from scipy.optimize import curve_fit

sys.path.insert(0, str(Path(__file__).resolve().parent))
from docstring_cli import parser_from_docstring  # noqa: E402
from revsph_runs import REPO, write_dict_rows  # noqa: E402

L, U1, S0 = 0.01, 40.0, 725.5
MODE = np.sqrt(2.0) * np.pi / L  # |k| of the mode cos(pi x/L) cos(pi y/L)
PAPER_WINDOW = np.sqrt(2.0) * L / U1


def read_probes(paths):
    """{run: (t, s, s_eq25)} from every file, cosine runs only."""
    runs = {}
    for path in paths:
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                if "cosine" in row["run"]:
                    runs.setdefault(row["run"], []).append(
                        [float(row[k]) for k in ("time", "probe_entropy", "eq25")])
    return {run: tuple(np.array(rows).T) for run, rows in runs.items()}


def fit_wave(t, s, speed_guess):
    """(c, a, w, phi) of s = c + a cos(w t + phi), least squares from the guess w = |k| u."""
    def wave(time, c, a, w, phi):
        return c + a * np.cos(w * time + phi)
    start = [np.mean(s), 0.5 * (np.max(s) - np.min(s)), MODE * speed_guess, 0.0]
    parameters, _ = curve_fit(wave, t, s, p0=start)
    c, a, w, phi = parameters
    if a < 0:  # one sign convention: a > 0
        a, phi = -a, phi + np.pi
    return c, a, w, (phi + np.pi) % (2 * np.pi) - np.pi


def lag_error(t, probe_fit, exact_fit, window):
    """eps1 the fitted wave alone gives, 0.5 max over t <= window of the mode's difference, in
    units of the exact amplitude."""
    _, a, w, phi = probe_fit
    _, a25, w25, phi25 = exact_fit
    time = np.linspace(0.0, min(window, t[-1]), 4001)
    return 0.5 * np.max(np.abs(a / a25 * np.cos(w * time + phi) - np.cos(w25 * time + phi25)))


def measured_errors(paths):
    errors = {}
    for path in paths:
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                if "eps1_period" in row:
                    errors[row["run"]] = (float(row["eps1_paper_window"]), float(row["eps1_period"]))
                elif "eps1" in row:  # an older file: eps1 over the period only
                    errors[row["run"]] = (np.nan, float(row["eps1"]))
    return errors


def summarise(run, t, s, s_exact, errors, wide):
    exact = fit_wave(t, s_exact, 18.83)
    u2 = exact[2] / MODE
    probe = fit_wave(t, s, u2)
    speed = probe[2] / MODE
    n = int(re.search(r"-N(\d+)-", run).group(1))
    lag = (exact[2] - probe[2]) * t[-1] + (exact[3] - probe[3])
    window, period = errors.get(run, (np.nan, np.nan))
    # A s0 from eq. (25) at t = 0: the probe sits where cos(pi x/L) cos(pi y/L) = 1/2.
    scale = 2.0 * (s_exact[0] - S0)
    early = t <= PAPER_WINDOW * (1 + 1e-9)
    return dict(run=run, N=n, support_over_dr=6 if run.endswith("-2h") or run in wide else 3, u2=u2,
                probe_speed=speed, speed_difference=speed / u2 - 1.0, phase_lag_at_end=lag,
                amplitude_ratio=probe[1] / exact[1], t_end=t[-1],
                eps1_lag_paper_window=lag_error(t, probe, exact, PAPER_WINDOW),
                eps1_lag_whole=lag_error(t, probe, exact, t[-1]),
                eps1_paper_window=window, eps1_period=period,
                probe_error_paper_window=np.max(np.abs(s - s_exact)[early]) / scale,
                probe_error_whole=np.max(np.abs(s - s_exact)) / scale)


def main():
    parser = parser_from_docstring(__doc__)
    parser.add_argument("probes", nargs="+")
    parser.add_argument("--out", default=str(REPO / "docs" / "figures" /
                                             "superfluid_second_sound_speed.csv"))
    parser.add_argument("--errors", nargs="*", default=[])
    parser.add_argument("--wide", nargs="*", default=[])
    args = parser.parse_args()
    errors = measured_errors(args.errors)
    rows = [summarise(run, *series, errors, args.wide)
            for run, series in read_probes(args.probes).items()]
    rows.sort(key=lambda r: (r["support_over_dr"], r["N"]))
    write_dict_rows(args.out, rows)
    for r in rows:
        print(f"{r['run']}: u = {r['probe_speed']:.4f} m/s against u2 = {r['u2']:.4f} "
              f"({100 * r['speed_difference']:+.3f} %), {r['phase_lag_at_end']:.4f} rad behind "
              f"at t = {r['t_end'] * 1e3:.3f} ms, amplitude x {r['amplitude_ratio']:.4f}; eps1 "
              f"from the lag alone {r['eps1_lag_paper_window']:.4f} / {r['eps1_lag_whole']:.4f}, "
              f"measured {r['eps1_paper_window']:.4f} / {r['eps1_period']:.4f}; the probe off eq. "
              f"(25) by {r['probe_error_paper_window']:.4f} / {r['probe_error_whole']:.4f} of A s0")
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
