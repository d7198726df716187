"""Figures of one dyncontact run from its log (the done line and the cost-per-step line that
Simulation::finish() writes) and from its /usr/bin/time -v log, for the bench tables
(performance_table.py, scaling_table.py, step_cost_table.py)."""
import re

DONE = re.compile(r"done, (\d+) steps .*?, (\d+) linear solves \((\d+) factorizations, "
                  r"(\d+) low-rank updates\), wall time ([0-9.e+-]+) s \((.*?)\)\. Results")
PER_STEP = re.compile(r"cost per step ([0-9.e+-]+) ms without active pairs \((\d+) steps\), "
                      r"([0-9.e+-]+) ms with active pairs \((\d+) steps\)")


def parse_log(text):
    """The run's counts, wall time of the stepping [s], phases {name: s}, DoFs and the mean
    wall time of a step without / with active pairs [s]; None if the run did not finish."""
    done = DONE.search(text)
    if not done:
        return None
    dofs = re.search(r"(\d+) displacement DoFs", text)
    per_step = PER_STEP.search(text)
    return {"steps": int(done.group(1)), "solves": int(done.group(2)),
            "factorizations": int(done.group(3)), "low_rank_updates": int(done.group(4)),
            "wall": float(done.group(5)),
            "phases": dict((name.strip(), float(value)) for name, value in
                           re.findall(r"([a-z -]+) ([0-9.e+-]+) s", done.group(6))),
            "dofs": int(dofs.group(1)) if dofs else 0,
            "free_step": float(per_step.group(1)) / 1e3 if per_step else None,
            "contact_step": float(per_step.group(3)) / 1e3 if per_step else None,
            "contact_steps": int(per_step.group(4)) if per_step else 0}


def parse_time_log(text):
    """Peak resident memory [MB] and elapsed wall time of the whole process [s] from
    /usr/bin/time -v (None where missing)."""
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
    elapsed = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (?:(\d+):)?(\d+):([0-9.]+)",
                        text)
    return {"rss_mb": int(rss.group(1)) / 1024 if rss else None,
            "elapsed": (3600 * int(elapsed.group(1) or 0) + 60 * int(elapsed.group(2)) +
                        float(elapsed.group(3))) if elapsed else None}
