#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the reference documentation (Doxygen, Debian's doxygen package) into
# OUTPUT (default build/reference): OUTPUT/html/index.html. Fails, printing
# them, on any warning (an undocumented public entity, a bad command).
set -euo pipefail
cd "$(dirname "$0")/.."
output="$(realpath -m "${1:-build/reference}")"
mkdir -p "$output"
rm -f "$output/warnings.txt"
status=0
EDGE_SWAPPING_3_REFERENCE_OUTPUT="$output" doxygen doc/Edge_swapping_3/reference/Doxyfile || status=$?
if [ -s "$output/warnings.txt" ]; then
  cat "$output/warnings.txt" >&2
  echo "make_reference: $(wc -l < "$output/warnings.txt") warnings" >&2
  exit 1
fi
[ "$status" -eq 0 ] || exit "$status"
echo "make_reference: no warnings; $output/html/index.html"
