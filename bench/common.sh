# Sourced by every bench/*.sh script: strict mode, the repository root as working directory, Open
# MPI allowed to run as root, and a Release build of dyncontact (the only build to time).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2 --target dyncontact >/dev/null
