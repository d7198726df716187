"""What the friction checks of the CLI tests share: a run's history.csv as numbers, and checks
that print one line each and fail the script at its end if any did not hold."""
import csv
import sys


def read_history(directory):
    """The rows of DIRECTORY/history.csv, each a dict of its columns as floats."""
    with open(f"{directory}/history.csv", newline="") as handle:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(handle)]


class Checks:
    """Checks that print their figures; finish() exits 1 if any failed."""

    def __init__(self):
        self.failures = []

    def _report(self, name, ok, text):
        print(f"{name}: {text} {'ok' if ok else 'FAILED'}")
        if not ok:
            self.failures.append(name)

    def bound(self, name, value, bound, above=False):
        """value <= bound (above: value >= bound)."""
        ok = value >= bound if above else value <= bound
        self._report(name, ok, f"{value:.3g} ({'at least' if above else 'bound'} {bound:g})")

    def relative(self, name, value, reference, tolerance, relative=True):
        """|value - reference| <= tolerance, relative to |reference| unless `relative` is false (or
        the reference is zero)."""
        scale = abs(reference) if relative and reference != 0 else 1.0
        error = abs(value - reference) / scale
        self._report(name, error <= tolerance,
                     f"{value:.15g} vs {reference:.15g}, {'relative ' if scale != 1.0 else ''}error "
                     f"{error:.3g} (bound {tolerance:g})")

    def finish(self):
        if self.failures:
            print("FAILED:", ", ".join(self.failures))
            sys.exit(1)
