#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Fuzzes the readers: builds one libFuzzer target per reader with clang
# (AddressSanitizer and UndefinedBehaviorSanitizer) and runs each for
# SECONDS (default 60), from the seed corpus in test/Edge_swapping_3/fuzz/corpus
# (the package's readers) or laboratory/test/fuzz/corpus (the laboratory's).
#
#   bash scripts/fuzz.sh [SECONDS] [READER...]    readers: node ele medit msh vtu topcom case_json results streamed trace
#
# The growing corpus stays in build-fuzz/corpus/READER; a finding (crash,
# sanitizer report, uncaught exception, time-out over 10 s, over 2 GB) is
# written to build-fuzz/findings/READER/ and ends that reader's run. A
# summary line per reader goes to build-fuzz/summary.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
[ $# -gt 0 ] && shift
readers=("$@")
[ ${#readers[@]} -gt 0 ] || readers=(node ele medit msh vtu topcom case_json results streamed trace)

bash scripts/install_dependencies.sh clang libclang-rt-14-dev
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DEDGE_SWAPPING_3_FUZZ=ON \
      -DBUILD_TESTING=OFF -DEDGE_SWAPPING_3_BUILD_EXAMPLES=OFF -DEDGE_SWAPPING_3_BUILD_BENCHMARKS=OFF > /dev/null
cmake --build build-fuzz -j "$(nproc)" --target "${readers[@]/#/fuzz_}"

: > build-fuzz/summary.txt
status=0
for r in "${readers[@]}"; do
  mkdir -p "build-fuzz/corpus/$r" "build-fuzz/findings/$r"
  log="build-fuzz/fuzz_$r.log"
  echo "fuzz_$r: ${seconds} s"
  seeds=test/Edge_swapping_3/fuzz/corpus/$r
  [ -d "$seeds" ] || seeds=laboratory/test/fuzz/corpus/$r
  if ./build-fuzz/bin/fuzz_"$r" "build-fuzz/corpus/$r" "$seeds" \
       -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
       -artifact_prefix="build-fuzz/findings/$r/" -print_final_stats=1 > "$log" 2>&1; then
    result="no finding"
  else
    result="FINDING (see $log and build-fuzz/findings/$r/)"
    status=1
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  line="fuzz_$r: $seconds s, $runs executions, corpus $(ls "build-fuzz/corpus/$r" | wc -l) files: $result"
  echo "$line" | tee -a build-fuzz/summary.txt
done
exit $status
