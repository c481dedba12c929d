#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the laboratory's results report, one HTML page with its figures
# embedded, from conjectures.md and traces.md: laboratory/doc/report/conjectures.html.
# Needs pandoc (Debian: apt-get install pandoc); not part of the build or the tests.
set -euo pipefail
cd "$(dirname "$0")"
if ! command -v pandoc > /dev/null; then
  echo "build_report.sh: pandoc is not installed (apt-get install pandoc)" >&2
  exit 2
fi
mkdir -p report
pandoc conjectures.md traces.md --from gfm --to html5 --standalone --self-contained --toc \
  --metadata title="Edge_swapping_3: the conjecture laboratory" \
  --metadata date="$(git log -1 --format=%cs 2> /dev/null || true)" \
  -o report/conjectures.html
echo "build_report.sh: wrote $(pwd)/report/conjectures.html"
