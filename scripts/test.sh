#!/usr/bin/env bash
# Sets up (the test suite's packages included), builds everything and runs
# the whole test suite through ctest (in build/, Release; it includes the
# fuzz test, tests/test_fuzz.cpp), then the sanitizer job: a subset of the
# tests built with AddressSanitizer and UndefinedBehaviorSanitizer in
# build-asan/ (scripts/test_sanitizers.sh says which and why).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --tests
ctest --test-dir build --output-on-failure -j"$(nproc)"
scripts/test_sanitizers.sh
