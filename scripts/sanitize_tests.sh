#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The whole test suite under AddressSanitizer and UndefinedBehaviorSanitizer
# (g++), the program included: too slow for CI on two cores, so run by hand
# before closing work on the readers, the flips or the drivers.
#
#   bash scripts/sanitize_tests.sh [CTEST ARGS...]
#
# Builds in build-sanitize (RelWithDebInfo, -O1) and runs ctest there. Any
# sanitizer report ends its process with an error, so the test fails. The
# test that limits the address space (threads that cannot start) is skipped:
# ASan reserves terabytes of shadow memory.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
flags="-O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined"
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$flags" \
      -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
      -DEDGE_SWAPPING_3_BUILD_BENCHMARKS=OFF -DEDGE_SWAPPING_3_BUILD_EXAMPLES=ON > /dev/null
cmake --build build-sanitize -j "$(nproc)"
export EDGE_SWAPPING_3_SANITIZED=1
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build-sanitize --output-on-failure -j "$(nproc)" "$@"
