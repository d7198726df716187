#!/usr/bin/python3
"""Reads one CalculiX run of make_deck.py (DIR/sphere.dat, DIR/deck.json, DIR/ccx.log and
DIR/time.log if present) and writes
  DIR/history.csv   time,contact_force (the full-ring force: 180 x the 2-degree wedge's; for the
                    3D deck of make_deck_3d.py the whole sphere's: 4 x the quarter's)
  DIR/summary.csv   one row: the run's figures (header below)
  DIR/history.png   the force history, zoomed on the contact (if matplotlib is there)
and prints the summary row as one line.

Metrics (as dyncontact's measure_impact() and bench/hertz_limit.sh do):
  peak      the vertex of the parabola through the largest sample and its two neighbours
  duration  end - start, each from F^(2/3) (linear in the approach for Hertz) extrapolated
            linearly to zero through the first (last) two positive samples, clamped to the step
            before the first (after the last) positive sample
  impulse   the trapezoid rule over all samples; a full elastic bounce gives 2 m v
The 3D deck's summary (SUMMARY_FIELDS_3D) compares with the finite-sphere law as well as Hertz.
Usage: analyze.py DIR [--label NAME] [--plot-window T0 T1]
"""
import argparse
import csv
import json
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import impact_measures  # noqa: E402

SUMMARY_FIELDS = ["label", "rho", "material", "pole_size", "zone_radius", "far_size", "pole_edge",
                  "nodes", "elements", "equations", "dt", "start_time", "end_time", "increments",
                  "iterations", "wall_s", "peak_rss_mb", "peak", "duration", "impulse",
                  "hertz_peak", "hertz_duration", "two_m_v", "peak_vs_hertz_pct",
                  "duration_vs_hertz_pct", "impulse_vs_2mv_pct", "contact_start", "contact_end"]
SUMMARY_FIELDS_3D = ["label", "element", "material", "n", "nr", "pole_grading", "penalty",
                     "launch", "contact", "slave", "pole_edge", "nodes", "elements", "slave_faces",
                     "equations", "dt", "start_time", "end_time", "increments", "iterations",
                     "wall_s", "peak_rss_mb", "peak", "duration", "impulse", "law_peak",
                     "law_duration", "two_m_v", "peak_vs_law_pct", "duration_vs_law_pct",
                     "impulse_vs_2mv_pct", "peak_vs_hertz_pct", "duration_vs_hertz_pct",
                     "contact_start", "contact_end"]


def read_history(dat, wedge_factor, time_offset, component=1, sign=-1.0):
    """(time, full-ring contact force) from the *NODE PRINT, TOTALS=ONLY blocks of RF on the plate.
    RF is the force the supports exert on the plate; in the axisymmetric deck the sphere pushes
    the plate toward +y (away from it), so the contact force is minus the y component (the
    defaults); in the 3D deck toward -z: plus the z component (component 2, sign +1)."""
    hist = {}
    lines = open(dat).read().split("\n")
    pat = re.compile(r"total force \(fx,fy,fz\) for set NPLATE and time\s+(\S+)")
    for i, line in enumerate(lines):
        m = pat.search(line)
        if not m:
            continue
        t = float(m.group(1)) + time_offset
        vals = next(l for l in lines[i + 1:] if l.strip()).split()
        hist[round(t, 12)] = sign * float(vals[component]) * wedge_factor
    times = sorted(hist)
    return times, [hist[t] for t in times]


def metrics(t, f):
    peak, peak_time, start, end = impact_measures.measures(t, f)
    impulse = sum(0.5 * (f[i] + f[i + 1]) * (t[i + 1] - t[i]) for i in range(len(t) - 1))
    return peak, end - start, impulse, start, end, peak_time


def ccx_log_figures(log):
    text = open(log).read() if os.path.exists(log) else ""
    m = re.search(r"number of equations\s+(\d+)", text)
    return int(m.group(1)) if m else None


def sta_figures(sta):
    incs = iters = 0
    if os.path.exists(sta):
        for line in open(sta):
            f = line.split()
            if len(f) >= 7 and f[0].isdigit() and f[1].isdigit():
                incs += 1
                iters += int(f[3])
    return incs, iters


def time_figures(path):
    wall = rss = None
    if os.path.exists(path):
        text = open(path).read()
        m = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", text)
        if m:
            parts = [float(p) for p in m.group(1).split(":")]
            wall = sum(p * 60 ** (len(parts) - 1 - k) for k, p in enumerate(parts))
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
        if m:
            rss = int(m.group(1)) / 1024.0
        m = re.fullmatch(r"\s*([\d.]+)\s+(\d+)\s*", text)  # /usr/bin/time -f "%e %M"
        if m:
            wall, rss = float(m.group(1)), int(m.group(2)) / 1024.0
        m = re.search(r"^real\s+(\S+)", text, re.M)  # bash `time -p` fallback
        if wall is None and m:
            wall = float(m.group(1))
    return wall, rss


def plot(path, t, f, info, window):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("analyze.py: no matplotlib, no plot", file=sys.stderr)
        return
    h = info["hertz"]
    fig, ax = plt.subplots(figsize=(7, 4.2))
    sel = [i for i, x in enumerate(t) if window[0] <= x <= window[1]]
    element = info.get("element", "CAX8")
    ax.plot([t[i] for i in sel], [f[i] for i in sel], "o-", ms=2.5, lw=1,
            label=f"CalculiX {element}, pole edge {info['pole_edge']:.3g}")
    # Hertz's history F(t), from the quasi-static impact ODE: m w'' = -K w^1.5.
    import math
    k = 4.0 / 3.0 * info["E"] / (1 - info["nu"] ** 2) * math.sqrt(info["R"])
    t_touch = info.get("contact_time", 2.0)
    m, w, v, tt, dt = h["mass"], 0.0, info["v"], t_touch, h["duration"] / 4000
    ht, hf = [tt], [0.0]
    while True:
        a1 = -k * max(w, 0) ** 1.5 / m
        w_mid, v_mid = w + 0.5 * dt * v, v + 0.5 * dt * a1
        a2 = -k * max(w_mid, 0) ** 1.5 / m
        w, v, tt = w + dt * v_mid, v + dt * a2, tt + dt
        if w <= 0:
            break
        ht.append(tt)
        hf.append(k * w ** 1.5)
    ax.plot(ht, hf, "k--", lw=1, label="Hertz")
    ax.set_xlim(*window)
    ax.set_xlabel("t")
    ax.set_ylabel("contact force (whole sphere)" if "law" in info else
                  "contact force (full ring)")
    mat = "NLGEOM (St Venant-Kirchhoff)" if info["nlgeom"] else "linear elastic"
    ax.set_title(f"sphere on rigid plane, rho = {info['rho']:g}, {mat}, dt = {info['dt']:g}, "
                 f"alpha = {info['alpha']:g}", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("--label", default=None)
    ap.add_argument("--plot-window", type=float, nargs=2, default=None)
    a = ap.parse_args()
    info = json.load(open(os.path.join(a.dir, "deck.json")))
    t, f = read_history(os.path.join(a.dir, "sphere.dat"), info["wedge_factor"],
                        info["start_time"], info.get("force_component", 1),
                        info.get("force_sign", -1.0))
    if not t:
        sys.exit(f"analyze.py: no force history in {a.dir}/sphere.dat")
    with open(os.path.join(a.dir, "history.csv"), "w") as out:
        out.write("time,contact_force\n")
        for x, y in zip(t, f):
            out.write(f"{x:.10g},{y:.10g}\n")
    h = info["hertz"]
    peak, duration, impulse, start, end, _ = metrics(t, f)
    equations = ccx_log_figures(os.path.join(a.dir, "ccx.log"))
    incs, iters = sta_figures(os.path.join(a.dir, "sphere.sta"))
    wall, rss = time_figures(os.path.join(a.dir, "time.log"))
    row = {
        "label": a.label or os.path.basename(os.path.normpath(a.dir)),
        "rho": info["rho"], "material": "nlgeom" if info["nlgeom"] else "linear",
        "pole_size": info.get("pole_size"), "zone_radius": round(info.get("zone_radius", 0), 6),
        "far_size": info.get("far_size"), "pole_edge": round(info["pole_edge"], 5),
        "nodes": info["nodes"], "elements": info["elements"], "equations": equations,
        "dt": info["dt"], "start_time": info["start_time"], "end_time": info["end_time"],
        "increments": incs, "iterations": iters,
        "wall_s": None if wall is None else round(wall, 2),
        "peak_rss_mb": None if rss is None else round(rss, 1),
        "peak": round(peak, 5), "duration": round(duration, 6), "impulse": round(impulse, 5),
        "hertz_peak": round(h["peak"], 5), "hertz_duration": round(h["duration"], 6),
        "two_m_v": round(h["impulse"], 5),
        "peak_vs_hertz_pct": round(100 * (peak / h["peak"] - 1), 3),
        "duration_vs_hertz_pct": round(100 * (duration / h["duration"] - 1), 3),
        "impulse_vs_2mv_pct": round(100 * (impulse / h["impulse"] - 1), 3),
        "contact_start": round(start, 6), "contact_end": round(end, 6),
    }
    fields = SUMMARY_FIELDS
    if "law" in info:  # the 3D deck
        law = info["law"]
        fields = SUMMARY_FIELDS_3D
        row.update({
            "element": info["element"], "n": info["n"], "nr": info["nr"],
            "pole_grading": info["pole_grading"], "penalty": info["penalty"],
            "launch": info["launch"], "contact": info["contact"],
            "slave": info.get("slave", "sphere"),
            "slave_faces": info["slave_faces"],
            "law_peak": round(law["peak"], 5), "law_duration": round(law["duration"], 6),
            "peak_vs_law_pct": round(100 * (peak / law["peak"] - 1), 3),
            "duration_vs_law_pct": round(100 * (duration / law["duration"] - 1), 3),
        })
    with open(os.path.join(a.dir, "summary.csv"), "w", newline="") as out:
        w = csv.DictWriter(out, fieldnames=fields, extrasaction="ignore")
        w.writeheader()
        w.writerow(row)
    t_touch = info.get("contact_time", 2.0)
    window = a.plot_window or (t_touch - 0.01, t_touch + 1.1 * h["duration"] + 0.002)
    plot(os.path.join(a.dir, "history.png"), t, f, info, window)
    print(" ".join(f"{k}={row[k]}" for k in fields))


if __name__ == "__main__":
    main()
