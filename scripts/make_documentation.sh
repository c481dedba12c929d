#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the documentation (Doxygen, Debian's doxygen package): the user
# manual, the program's reference, the file formats, the examples and the API
# reference, into OUTPUT (default build/documentation): OUTPUT/html/index.html.
# Fails, printing them, on any warning (an undocumented public entity, a bad
# command, a link that goes nowhere).
set -euo pipefail
cd "$(dirname "$0")/.."
output="$(realpath -m "${1:-build/documentation}")"
mkdir -p "$output"
rm -f "$output/warnings.txt"
status=0
EDGE_SWAPPING_3_REFERENCE_OUTPUT="$output" doxygen doc/Edge_swapping_3/Doxyfile || status=$?
if [ -s "$output/warnings.txt" ]; then
  cat "$output/warnings.txt" >&2
  echo "make_documentation: $(wc -l < "$output/warnings.txt") warnings" >&2
  exit 1
fi
[ "$status" -eq 0 ] || exit "$status"
echo "make_documentation: no warnings; $output/html/index.html"
