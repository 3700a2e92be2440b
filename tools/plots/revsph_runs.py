"""Helpers the figure scripts share: finding revsph, making runs, reading their CSV and snapshots."""

import csv
import shlex
import subprocess
import sys
import tomllib
from pathlib import Path

import h5py
import numpy as np

REPO = Path(__file__).resolve().parents[2]


def find_revsph(given):
    """The revsph binary: `given`, else build/bin/revsph, else build-*/bin/revsph."""
    if given:
        return Path(given)
    for candidate in [REPO / "build" / "bin" / "revsph", *sorted(REPO.glob("build-*/bin/revsph"))]:
        if candidate.is_file():
            return candidate
    sys.exit("no revsph binary: build it or pass --revsph")


def run_exists(run):
    """A finished run (summary.json) or one a session's end cut short (snapshots, continued by
    segments NAME-2, ... with `revsph run --from`): either is read, neither is made again."""
    return (run / "summary.json").is_file() or any((run / "snapshots").glob("step_*.h5"))


def make_missing_runs(runs, commands, revsph, threads=None, may_stop=()):
    """Runs `revsph ARGS --out RUNS/NAME --force` for each NAME that does not exist yet. A run
    named in `may_stop` may end on a model's fault (exit 3: where and why it stopped is the
    measurement, in its summary.json); any other failure stops the script."""
    for name, arguments in commands.items():
        if run_exists(runs / name):
            continue
        command = [str(revsph), *arguments, "--out", str(runs / name), "--force"]
        if threads:
            command += ["--threads", threads]
        print("+", shlex.join(command), flush=True)
        status = subprocess.run(command).returncode
        if status != 0 and not (status == 3 and name in may_stop):
            raise subprocess.CalledProcessError(status, command)


def missing_runs(runs, names):
    return [n for n in names if not run_exists(runs / n)]


def save_figure(fig, path, dpi=110):
    """Lays out, writes and closes a matplotlib figure."""
    import matplotlib.pyplot as plt  # here: the modules importing this one need not plot

    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)


def label_axes(ax, xlabel, ylabel, legend=True):
    """Names the axes and lays a light grid under the curves, with a small legend (legend=True):
    one finish for the panels of a figure so that they read alike."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if legend:
        ax.legend(fontsize=7)
    ax.grid(True, alpha=0.3)


def fit_sinusoid(t, y, omegas):
    """Least-squares y = c + a sin(w t) + b cos(w t), best w of `omegas`."""
    best = None
    for w in omegas:
        basis = np.c_[np.ones_like(t), np.sin(w * t), np.cos(w * t)]
        coefficients = np.linalg.lstsq(basis, y, rcond=None)[0]
        residual = np.sum((basis @ coefficients - y) ** 2)
        if best is None or residual < best[0]:
            best = (residual, w, coefficients)
    return best[1], best[2], np.sqrt(best[0] / len(t))


def read_csv(path):
    """Columns by name; revsph's header cells `name [unit]` are read by their names."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(row for row in f if not row.startswith("#")))
    return {name.split(" [")[0]: np.array([float(r[name]) for r in rows]) for name in rows[0]}


def write_csv(path, columns):
    names = list(columns)
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(names)
        for row in zip(*(columns[n] for n in names)):
            writer.writerow([f"{v:.10g}" for v in row])


def write_dict_rows(path, rows):
    """Rows of equal keys (dicts) as a CSV with those keys as its header, numbers to 6 digits."""
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        for row in rows:
            writer.writerow({k: v if isinstance(v, str) else f"{v:.6g}" for k, v in row.items()})


def snapshots(run):
    return sorted((run / "snapshots").glob("step_*.h5"))


def case_of(run):
    """The case file of a run, from its first snapshot, with the run's --set overrides applied."""
    with h5py.File(snapshots(run)[0]) as f:
        case = tomllib.loads(f.attrs["case_text"])
        stored = f.attrs.get("overrides")
        # An empty list is stored as an HDF5 empty attribute (h5py.Empty), not as [].
        overrides = [] if stored is None or isinstance(stored, h5py.Empty) else list(stored)
    for override in overrides:
        key, value = override.split("=", 1)
        node = case
        *parents, last = key.split(".")
        for part in parents:
            name, _, index = part.partition("[")
            node = node.setdefault(name, {})
            if index:
                node = node[int(index.rstrip("]"))]
        try:
            node[last] = tomllib.loads(f"v = {value}")["v"]
        except tomllib.TOMLDecodeError:
            node[last] = value  # a bare word is a string, as for revsph's --set
    return case


def write_report(path, report):
    lines = ["| quantity | value |", "|---|---|"] + [f"| {k} | {v} |" for k, v in report]
    path.write_text("\n".join(lines) + "\n")
    for key, value in report:
        print(f"{key}: {value}")


def figure_parser(doc, runs="out/shtc", out=REPO / "docs" / "figures" / "shtc", only=None):
    """The options every figure script shares (see its docstring); with `only` (the script's
    runs), --only NAME ... chooses some of them (chosen_runs)."""
    from docstring_cli import parser_from_docstring

    parser = parser_from_docstring(doc)
    parser.add_argument("--runs", default=runs)
    parser.add_argument("--out", default=str(out))
    parser.add_argument("--make-runs", action="store_true")
    parser.add_argument("--revsph")
    parser.add_argument("--threads")
    if only is not None:
        parser.add_argument("--only", nargs="*", default=list(only))
    return parser


def chosen_runs(parser, args, runs_table):
    """The runs --only names, in the table's order; an unknown name is a usage error."""
    unknown = [n for n in args.only if n not in runs_table]
    if unknown:
        parser.error(f"--only: unknown run {', '.join(unknown)} (known: {', '.join(runs_table)})")
    return [n for n in runs_table if n in args.only]


def figure_script_main(args, runs_table, makers, report_name, may_stop=()):
    """Makes the missing runs if asked (make_missing_runs, `may_stop` as there), calls each
    maker(runs, out, report) whose runs all exist, writes the report. Returns the exit status:
    0 only if every maker ran."""
    runs, out = Path(args.runs), Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    if args.make_runs:
        make_missing_runs(runs, runs_table, find_revsph(args.revsph), args.threads, may_stop)
    report = []
    made = True
    for needed, make in makers:
        missing = missing_runs(runs, needed)
        if missing:
            print(f"skipped {make.__name__}: missing runs {', '.join(missing)} in {runs} "
                  "(use --make-runs)")
            made = False
            continue
        make(runs, out, report)
    write_report(out / report_name, report)
    print(f"wrote {out}/")
    return 0 if made else 1


def run_rows_main(doc, default_runs, name, runs, command, draw_row, panels, panel_width=5.0):
    """main() of a script whose figure has one row of `panels` panels per run: for each (run,
    value) of `runs`, draw_row(fig, axes, RUNS / run, value, columns, report); writes
    OUT/name.png, OUT/name.csv (the columns) and OUT/name.md (the report), OUT defaulting to
    docs/figures/name. command(value) gives a run's revsph arguments for --make-runs."""
    parser = figure_parser(doc, default_runs, REPO / "docs" / "figures" / name)
    args = parser.parse_args()

    def make_figure(runs_dir, out, report):
        import matplotlib.pyplot as plt  # here: the modules importing this one need not plot
        fig, axes = plt.subplots(len(runs), panels, figsize=(panel_width * panels, 5 * len(runs)),
                                 squeeze=False)
        columns = {}
        for row, (run, value) in zip(axes, runs.items()):
            draw_row(fig, row, runs_dir / run, value, columns, report)
        fig.tight_layout()
        save_figure(fig, out / f"{name}.png")
        write_csv(out / f"{name}.csv", columns)

    return figure_script_main(args, {run: command(value) for run, value in runs.items()},
                              [(list(runs), make_figure)], f"{name}.md")


def chosen_runs_main(doc, default_runs, runs_table, command, make_figures, report_name):
    """main() of a figure script whose one maker, make_figures(runs, out, report, names), draws
    the runs that --only chooses (all of runs_table by default), so that such scripts cannot
    drift apart in their options: those of figure_parser with --runs defaulting to
    `default_runs` and --out to docs/figures; command(name) gives the revsph arguments that
    --make-runs runs `name` with. Returns figure_script_main's exit status."""
    parser = figure_parser(doc, default_runs, REPO / "docs" / "figures", runs_table)
    args = parser.parse_args()
    names = chosen_runs(parser, args, runs_table)
    return figure_script_main(
        args, {n: command(n) for n in names},
        [(names, lambda runs, out, report: make_figures(runs, out, report, names))],
        report_name)
