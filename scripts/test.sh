#!/usr/bin/env bash
# Sets up (the test suite's packages included), builds everything and runs
# the whole test suite through ctest (in build/, Release; it includes the
# fuzz test, tests/test_fuzz.cpp). The sanitizer build is a separate
# command, scripts/test_sanitizers.sh: it does not fit in CI's time on 2
# cores beside this one (README "Set-up").
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --tests
ctest --test-dir build --output-on-failure -j"$(nproc)"
