"""Peak force and contact interval of a sampled impact force history, as dyncontact's
measure_impact() (include/dyncontact/reference/impact_measures.h) defines them, for the bench
scripts that measure histories outside dyncontact (CalculiX's, bench/hertz_limit.sh's tables).

measures(times, forces) -> (peak, peak_time, start, end): the peak refined by the parabola through
the largest sample and its neighbours; start and end where F^(2/3) through the last two samples
of each side reaches zero (Hertz's F ~ d^(3/2) near the ends), kept within one step of the end
sample (else the neighbouring sample's time); uniform steps, compression positive.
"""


def measures(times, forces):
    positive = [i for i, f in enumerate(forces) if f > 0]
    first, last = positive[0], positive[-1]
    dt = times[1] - times[0]

    def end(i, j, outside):  # i: the sample at the end, j: its neighbour inside
        if outside is None:
            return times[i]  # the history begins (ends) in contact
        if len(positive) < 2 or forces[j] ** (2 / 3) <= forces[i] ** (2 / 3):
            return times[outside]
        y_i, y_j = forces[i] ** (2 / 3), forces[j] ** (2 / 3)
        zero = times[i] - y_i * (times[j] - times[i]) / (y_j - y_i)
        return zero if abs(zero - times[i]) <= dt * (1 + 1e-9) else times[outside]

    start = end(first, first + 1, first - 1 if first > 0 else None)
    stop = end(last, last - 1, last + 1 if last + 1 < len(times) else None)
    k = max(range(len(forces)), key=lambda i: forces[i])
    peak, peak_time = forces[k], times[k]
    if 0 < k < len(forces) - 1:
        f0, f1, f2 = forces[k - 1], forces[k], forces[k + 1]
        curvature = f0 - 2 * f1 + f2
        if curvature < 0:
            peak = f1 - (f2 - f0) ** 2 / (8 * curvature)
    return peak, peak_time, start, stop
