#!/usr/bin/env bash
# symcontact against FreeFEM + ff-Ipopt on the peers' Hertz quarter mesh, side by side, in one command:
# builds symcontact-bench (Release, no tests), runs `--case hertz2d-freefem` with one BLAS thread, and
# draws the log-log plot. See docs/performance.md, "Side by side with FreeFEM + IPOPT".
#
#   tools/bench_freefem_peer.sh [OUT_DIR] [bench options...]
#
# OUT_DIR (default bench-freefem) receives hertz2d_freefem.txt (the printed table), .csv and .png.
# Bench options replace the default "--repeat 3" (sizes: the bench's default h = 0.005 0.0025 0.00125), e.g.
#   tools/bench_freefem_peer.sh bench-freefem --h 0.005 0.0025 0.00125 0.000625 --repeat 3
# Environment: BUILD_DIR (default build-bench), THREADS (BLAS threads, default 1).
# Without FreeFEM (scripts/install-deps --peers installs it) the FreeFEM columns are skipped, not failed.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-bench-freefem}
[ $# -gt 0 ] && shift
args=("$@")
[ ${#args[@]} -eq 0 ] && args=(--repeat 3)
build=${BUILD_DIR:-build-bench}
threads=${THREADS:-1}

cd "$root"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DSYMCONTACT_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" --target symcontact_bench -j2 >/dev/null
mkdir -p "$out"
OPENBLAS_NUM_THREADS=$threads OMP_NUM_THREADS=$threads \
  "$build/benchmarks/symcontact-bench" --case hertz2d-freefem "${args[@]}" --csv "$out/hertz2d_freefem.csv" \
  | tee "$out/hertz2d_freefem.txt"
if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  /usr/bin/python3 tools/plot_freefem_peer.py "$out/hertz2d_freefem.csv" "$out/hertz2d_freefem.png" \
    --title "Hertz 2D quarter model (peers' mesh), $threads BLAS thread(s)"
else
  echo "bench_freefem_peer.sh: no matplotlib for /usr/bin/python3 (scripts/install-deps --pictures): no plot"
fi
