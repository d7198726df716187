#!/usr/bin/python3
"""Plot dyncontact run histories against the exact (and Hertz) reference solutions.

Usage: plot_results.py RUN_DIR [RUN_DIR ...] [--output DIR] [--labels L1 L2 ...] [--tmax T]

Each RUN_DIR holds history.csv and optionally exact.csv, hertz.csv and parameters.prm.
Writes tip_velocity.png, tip_acceleration.png, tip_displacement.png, contact_force.png
and energy.png, each with one panel per run side by side, and prints their paths.
"""
import argparse
import csv
import os
import re
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402  (backend must be chosen first)
import numpy as np  # noqa: E402

FE_COLOURS = ['tab:blue', 'tab:orange', 'tab:green', 'tab:purple', 'tab:brown']
EXACT_COLOURS = ['black', 'darkred', 'darkgreen', 'indigo', 'saddlebrown']
ENERGIES = ['kinetic', 'strain', 'total', 'algorithmic']
SPAN_RATIO = 100.0  # y-ranges differing by more than this get independent limits


class InputError(Exception):
    """A missing or malformed input file, reported without a traceback."""


def read_csv(path):
    """Read a numeric CSV with a header line into a dict column name -> float array.

    Blank lines, '#' comment lines and a trailing comma are tolerated; non-finite
    values (diverged runs) become NaN so that they leave gaps in the plots.
    """
    names, rows = None, []
    try:
        with open(path, newline='') as f:
            reader = csv.reader(f)
            for row in reader:
                row = [field.strip() for field in row]
                if row and row[-1] == '':
                    row.pop()
                if not row or row[0].startswith('#'):
                    continue
                if names is None:
                    names = row
                    continue
                if len(row) != len(names):
                    raise InputError(f'{path}, line {reader.line_num}: {len(row)} fields, '
                                     f'but the header has {len(names)}')
                try:
                    rows.append([float(x) for x in row])
                except ValueError as e:
                    raise InputError(f'{path}, line {reader.line_num}: {e}') from None
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        raise InputError(f'cannot read {path}: {e}') from None
    if names is None or not rows:
        raise InputError(f'{path}: no header line or no data rows')
    if 'time' not in names or len(set(names)) != len(names):
        raise InputError(f'{path}: header lacks a "time" column or repeats a column name')
    data = np.array(rows)
    data[~np.isfinite(data)] = np.nan
    return dict(zip(names, data.T))


def load_run(run_dir, tmax):
    """Load history.csv (required), exact.csv and hertz.csv (optional), clipped to t <= tmax."""
    history = os.path.join(run_dir, 'history.csv')
    if not os.path.isfile(history):
        raise InputError(f'{history}: no such file (is {run_dir} a run directory?)')
    run = {}
    for key in ('history', 'exact', 'hertz'):
        path = os.path.join(run_dir, key + '.csv')
        table = read_csv(path) if os.path.isfile(path) else {}
        if table and tmax is not None:
            keep = table['time'] <= tmax
            table = {name: values[keep] for name, values in table.items()}
        run[key] = table
    return run


def run_label(run_dir):
    """Label a run by 'set scheme' in the Time integration section of parameters.prm,
    falling back to the directory name."""
    sections = []
    try:
        with open(os.path.join(run_dir, 'parameters.prm')) as f:
            for line in f:
                line = line.split('#')[0]
                words = line.split()
                if words[:1] == ['subsection']:
                    sections.append(' '.join(words[1:]).lower())
                elif words[:1] == ['end'] and sections:
                    sections.pop()
                elif (words[:2] == ['set', 'scheme'] and '=' in line
                      and sections[-1:] == ['time integration']):
                    scheme = line.split('=', 1)[1].strip()
                    return f'{scheme} Newmark' if scheme in ('classical', 'modified') else scheme
    except (OSError, UnicodeDecodeError):
        pass
    return os.path.basename(os.path.normpath(run_dir))


def fe_curve(table, column, label, colour):
    """FE solution: thin line with markers on every k-th step (k odd, so that markers
    do not alias with a period-2 ringing and sit on alternate extremes)."""
    t = table['time']
    return t, table[column], dict(label=label, color=colour, lw=1.0, marker='o', ms=3,
                                  markevery=(len(t) // 60) | 1)


def reference_curve(table, column, label, colour, steps, ls='-'):
    """Reference (exact or Hertz) solution: thicker line drawn on top of the FE curves."""
    return table['time'], table[column], dict(label=label, color=colour, lw=1.6, ls=ls, zorder=3,
                                              drawstyle='steps-post' if steps else 'default')


def tip_curves(run, prefix, steps):
    """FE and exact curves of tip quantity `prefix` ('v_tip', ...) for every body."""
    history, exact = run['history'], run['exact']
    bodies = sorted(int(m.group(1)) for m in (re.fullmatch(prefix + r'_(\d+)', c) for c in history) if m)
    curves = []
    for i, body in enumerate(bodies):
        suffix = f', body {body}' if len(bodies) > 1 else ''
        column = f'{prefix}_{body}'
        curves.append(fe_curve(history, column, 'FE' + suffix, FE_COLOURS[i % len(FE_COLOURS)]))
        if column in exact:
            curves.append(reference_curve(exact, column, 'exact' + suffix,
                                          EXACT_COLOURS[i % len(EXACT_COLOURS)], steps))
    return curves


def force_curves(run):
    """FE contact force with the exact and Hertz references where available."""
    curves = []
    if 'contact_force' in run['history']:
        curves.append(fe_curve(run['history'], 'contact_force', 'FE', FE_COLOURS[0]))
    if 'contact_force' in run['exact']:
        curves.append(reference_curve(run['exact'], 'contact_force', 'exact', 'black', True))
    if 'contact_force' in run['hertz']:
        curves.append(reference_curve(run['hertz'], 'contact_force', 'Hertz', 'tab:red', False, '--'))
    return curves


def energy_curves(run):
    """FE kinetic, strain, total and algorithmic energies, and the exact total energy."""
    curves = [fe_curve(run['history'], f'{name}_energy', name, FE_COLOURS[i])
              for i, name in enumerate(ENERGIES) if f'{name}_energy' in run['history']]
    if 'total_energy' in run['exact']:
        curves.append(reference_curve(run['exact'], 'total_energy', 'exact total', 'black', False, '--'))
    return curves


def plot_figure(path, title, ylabel, panels, labels):
    """Draw one figure with a panel per run; return False (writing nothing) if there is no data.

    The panels share their y-limits unless the runs' data ranges differ by more than
    SPAN_RATIO, in which case the figure title says so.
    """
    if not any(panels):
        return False
    values = [np.concatenate([y for _, y, _ in curves] + [np.empty(0)]) for curves in panels]
    spans = [np.ptp(v[np.isfinite(v)]) for v in values if np.isfinite(v).any()]
    spans = [s for s in spans if s > 0]
    independent = len(spans) > 1 and max(spans) > SPAN_RATIO * min(spans)
    fig, axes = plt.subplots(1, len(panels), figsize=(5 * len(panels), 3.8),
                             sharey=not independent, squeeze=False)
    for ax, curves, label in zip(axes[0], panels, labels):
        for t, y, style in curves:
            ax.plot(t, y, **style)
        times = np.concatenate([t for t, _, _ in curves] + [np.empty(0)])
        if times.size and np.nanmax(times) > np.nanmin(times):
            ax.set_xlim(np.nanmin(times), np.nanmax(times))
        if curves:
            ax.legend(fontsize='small')
        else:
            ax.text(0.5, 0.5, 'no data', transform=ax.transAxes, ha='center', va='center')
        ax.set_title(label)
        ax.set_xlabel('time t')
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel(ylabel)
    if independent:
        title += f' (independent y-limits: ranges differ by more than {SPAN_RATIO:g}x)'
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return True


def parse_args(argv):
    """Parse the command line; argparse itself exits with code 2 on misuse."""
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('run_dirs', nargs='+', metavar='RUN_DIR', help='simulation output directory')
    parser.add_argument('--output', metavar='DIR',
                        help='where to write the PNGs (default: the first RUN_DIR)')
    parser.add_argument('--labels', nargs='+', metavar='L', help='panel titles, one per RUN_DIR')
    parser.add_argument('--tmax', type=float, metavar='T', help='clip the time axis at T')
    args = parser.parse_args(argv)
    if args.labels and len(args.labels) != len(args.run_dirs):
        parser.error(f'{len(args.labels)} labels given for {len(args.run_dirs)} run directories')
    return args


def main(argv=None):
    """Load all runs, write the figures and print their paths; return the exit code."""
    args = parse_args(argv)
    labels = args.labels or [run_label(d) for d in args.run_dirs]
    if not args.labels and len(set(labels)) < len(labels):  # e.g. two time steps, same scheme
        labels = [f'{label} ({os.path.basename(os.path.normpath(d))})'
                  for label, d in zip(labels, args.run_dirs)]
    output = args.output or args.run_dirs[0]
    figures = [('tip_velocity.png', 'Tip velocity', 'tip velocity v',
                lambda r: tip_curves(r, 'v_tip', True)),
               ('tip_acceleration.png', 'Tip acceleration', 'tip acceleration a',
                lambda r: tip_curves(r, 'a_tip', True)),
               ('tip_displacement.png', 'Tip displacement', 'tip displacement u',
                lambda r: tip_curves(r, 'u_tip', False)),
               ('contact_force.png', 'Contact force', 'contact force', force_curves),
               ('energy.png', 'Energy', 'energy', energy_curves)]
    try:
        runs = [load_run(d, args.tmax) for d in args.run_dirs]
        os.makedirs(output, exist_ok=True)
        for name, title, ylabel, make_curves in figures:
            path = os.path.join(output, name)
            if plot_figure(path, title, ylabel, [make_curves(run) for run in runs], labels):
                print(path)
    except (InputError, OSError) as e:
        print(f'{os.path.basename(sys.argv[0])}: error: {e}', file=sys.stderr)
        return 2
    return 0


if __name__ == '__main__':
    sys.exit(main())
