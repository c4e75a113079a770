#!/usr/bin/env bash
# Rewrites every figure README.md quotes from a run of the current code: the output of `scripts/demo`
# and of the first example (`symcontact run examples/block_2d/block.toml`), each between its pair of
# markers in README.md:
#   <!-- BEGIN readme_figures: demo -->   ...   <!-- END readme_figures: demo -->
#   <!-- BEGIN readme_figures: block -->  ...   <!-- END readme_figures: block -->
# and the problem file of that example itself (marker name block_file).
# It also copies the demo's results/demo/inclined.png to docs/img/inclined.png, the README's picture. The
# README quotes no other measured figure. The repository's path is written as /path/to/symcontact.
#   tools/readme_figures.sh            build in build/ (as scripts/demo does), results in results/demo
#   BUILD_DIR=dir tools/readme_figures.sh
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
build=${BUILD_DIR:-build}
readme="$root/README.md"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The demo, as a terminal shows it (its own lines on stdout, the solver's progress on stderr), and its
# picture of the three inclined-interface cases, which README.md shows as docs/img/inclined.png.
{ echo '$ scripts/demo'; BUILD_DIR="$build" OUT_DIR=results/demo scripts/demo 2>&1; } >"$tmp/demo.txt"
cp results/demo/inclined.png docs/img/inclined.png

# The first example, into a fresh folder.
rm -rf results/block
{
  echo '$ build/app/symcontact run examples/block_2d/block.toml --out results/block'
  "$build/app/symcontact" run examples/block_2d/block.toml --out results/block 2>&1
  echo '$ echo $?'
  echo 0
  echo '$ ls results/block'
  (cd results/block && ls | tr '\n' ' ' | sed 's/  *$//; s/ /  /g'; echo)
} >"$tmp/block.txt"

# The problem file as it is, without its leading comment lines.
sed '/^#/d' examples/block_2d/block.toml >"$tmp/block_file.txt"

# Replace what lies between each pair of markers by the new text in a fenced block.
for name in demo block block_file; do
  sed -i "s|$root|/path/to/symcontact|g" "$tmp/$name.txt"
  lang=console
  [ "$name" = block_file ] && lang=toml
  python3 - "$readme" "$name" "$tmp/$name.txt" "$lang" <<'EOF'
import sys
readme, name, lang = sys.argv[1], sys.argv[2], sys.argv[4]
output = open(sys.argv[3], encoding="utf-8").read().strip("\n")
text = open(readme, encoding="utf-8").read()
begin, end = f"<!-- BEGIN readme_figures: {name} -->", f"<!-- END readme_figures: {name} -->"
i, j = text.find(begin), text.find(end)
if i < 0 or j < i:
    sys.exit(f"readme_figures: {readme}: no '{begin}' ... '{end}' pair")
text = text[: i + len(begin)] + f"\n```{lang}\n" + output + "\n```\n" + text[j:]
open(readme, "w", encoding="utf-8").write(text)
EOF
done
echo "readme_figures: $readme updated (the demo, the first example and its problem file)"
