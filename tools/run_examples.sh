#!/usr/bin/env bash
# Solves every example of examples/ as it ships into OUT/<folder>_<case>/, one after another, with a
# given symcontact binary; with tools/compare_results.py it shows that a change of the code leaves every
# answer the same:
#   tools/run_examples.sh build/app/symcontact /tmp/before      # at the old commit (or a copy of its binary)
#   tools/run_examples.sh build/app/symcontact /tmp/after       # at the new one
#   tools/compare_results.py /tmp/before /tmp/after             # summary.json and CSVs, to 1e-10
# SKIP='ironing' leaves out the examples whose path matches that extended regular expression. A run's
# exit code and its stderr are kept in OUT/<name>.exit and OUT/<name>.log; the script itself exits 0.
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: $0 SYMCONTACT_BINARY OUT_DIR" >&2
  exit 2
fi
bin=$(realpath "$1")
out=$(realpath -m "$2")
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mkdir -p "$out"
cd "$root"
for toml in examples/*/*.toml; do
  if [ -n "${SKIP:-}" ] && [[ "$toml" =~ $SKIP ]]; then continue; fi
  name=$(basename "$(dirname "$toml")")_$(basename "$toml" .toml)
  rm -rf "${out:?}/$name"
  start=$(date +%s)
  set +e
  OPENBLAS_NUM_THREADS=1 "$bin" run "$toml" --out "$out/$name" 2> "$out/$name.log" > /dev/null
  code=$?
  set -e
  echo "$code" > "$out/$name.exit"
  echo "$toml: exit $code in $(( $(date +%s) - start )) s"
done
