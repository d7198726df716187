#!/usr/bin/env bash
# Message volumes of the large sphere impact (issue 27, move 6: the weak-scaling model), measured
# by Open MPI's monitoring components (pml, coll: OMPI_MCA_pml_monitoring_enable=2 separates the
# point-to-point messages the program sends from those Open MPI's collectives send inside). On
# each rank count given (default 2 4) two runs of bench/common.sh's run_large_sphere at
# Refinement REFINEMENT (default 3: 273,924 DoFs): 2 and 4 steps of dt = 0.0025, every one a
# contact step. The difference of the two is what steps 3 and 4 send, without the set-up (the
# graph gathered for METIS, MUMPS's analysis, the mass), per step: each rank's bytes sent
#   - point to point to other ranks: MUMPS's factorization (contribution blocks, the entries
#     sent to the fronts' ranks) and solves, Epetra's exports of matrix rows;
#   - inside collectives: every collective of every communicator (MUMPS's, Trilinos's, ours);
#   - of those, MPI_COMM_WORLD's collectives by their data volume: dyncontact's own whole-vector
#     sums (the internal force, once per residual evaluation) and the gathered solutions.
# Writes bench/results/message_volumes/refinement_R/ranks_N_steps_S.{log,time,*.prof} and prints a markdown
# table (largest rank and the mean over ranks). About 2 minutes per rank count at Refinement 3.
#   [REFINEMENT=3] bench/message_volumes.sh [RANKS...]
set -euo pipefail
source "$(dirname "$0")/common.sh"
refinement=${REFINEMENT:-3}
results=bench/results/message_volumes/refinement_$refinement
mkdir -p "$results"
ranks_list=("$@")
[ ${#ranks_list[@]} -gt 0 ] || ranks_list=(2 4)
for ranks in "${ranks_list[@]}"; do
  for steps in 2 4; do
    run=$results/ranks_${ranks}_steps_$steps
    rm -f "$run".*.prof
    OMPI_MCA_pml_monitoring_enable=2 OMPI_MCA_pml_monitoring_enable_output=3 \
      OMPI_MCA_pml_monitoring_filename="$run" \
      run_large_sphere "$run" "$ranks" "$refinement" "$(awk -v s=$steps 'BEGIN { print s * 0.0025 }')"
  done
done
/usr/bin/python3 - "$results" "${ranks_list[@]}" <<'PYTHON'
import glob, re, sys
results, ranks_list = sys.argv[1], sys.argv[2:]

def volumes(prefix):
    """Per rank: bytes sent point to point to other ranks, inside collectives, and the data
    volume of MPI_COMM_WORLD's collectives (Open MPI's monitoring output, one file per rank)."""
    per_rank = []
    for name in sorted(glob.glob(prefix + ".*.prof"), key=lambda n: int(n.split(".")[-2])):
        p2p = inside = world = 0
        communicator = None
        for line in open(name):
            fields = line.split("\t")
            if fields[0] == "E" and fields[1] != fields[2]:
                p2p += int(fields[3].split()[0])
            elif fields[0] == "I":
                inside += int(fields[3].split()[0])
            elif fields[0] == "D":
                communicator = fields[1]
            elif fields[0] in ("O2A", "A2O", "A2A") and communicator == "MPI_COMM_WORLD":
                world += int(fields[2].split()[0])
        per_rank.append((p2p, inside, world))
    return per_rank

def counts(log):
    text = open(log).read()
    solves, factorizations = map(int, re.search(
        r"(\d+) linear solves \((\d+) factorizations", text).groups())
    dofs = int(re.search(r"(\d+) displacement DoFs", text).group(1))
    return dofs, solves, factorizations

print("| ranks | DoFs | solves / factorizations per step | point to point, largest rank | inside collectives, largest rank | of those, MPI_COMM_WORLD's collectives (data), largest rank | sent in all (point to point and inside collectives), mean over ranks | set-up (the 2-step run less 2 steps), largest rank |")
print("|---|---|---|---|---|---|---|---|")
for ranks in ranks_list:
    short, long = (f"{results}/ranks_{ranks}_steps_{s}" for s in (2, 4))
    a, b = volumes(short), volumes(long)
    if len(a) != int(ranks) or len(b) != int(ranks):
        sys.exit(f"ranks {ranks}: expected {ranks} monitoring files per run in {results}")
    step = [[(y - x) / 2 for x, y in zip(ra, rb)] for ra, rb in zip(a, b)]
    setup = [ra[0] + ra[1] - 2 * (rs[0] + rs[1]) for ra, rs in zip(a, step)]
    dofs, solves_b, factorizations_b = counts(long + ".log")
    _, solves_a, factorizations_a = counts(short + ".log")
    mib = lambda x: f"{x / 2**20:.1f} MiB"
    print(f"| {ranks} | {dofs} | {(solves_b - solves_a) / 2:g} / {(factorizations_b - factorizations_a) / 2:g} | "
          + " | ".join(mib(max(r[k] for r in step)) for k in range(3))
          + f" | {mib(sum(r[0] + r[1] for r in step) / len(step))} | {mib(max(setup))} |")
PYTHON
