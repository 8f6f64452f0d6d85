#!/usr/bin/env bash
# Sets up (the test suite's packages included), builds everything and runs
# the whole test suite through ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --tests
ctest --test-dir build --output-on-failure -j"$(nproc)"
