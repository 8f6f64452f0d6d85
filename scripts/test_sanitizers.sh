#!/usr/bin/env bash
# The test suite built with AddressSanitizer and UndefinedBehaviorSanitizer
# (GCC's -fsanitize=address,undefined) in build-asan/, apart from the
# Release build in build/. Any report ends the test that triggered it
# (halt_on_error), so a report is a failed test. Called by scripts/test.sh
# after the Release suite; run it alone after scripts/setup.sh --tests.
#   scripts/test_sanitizers.sh           every test but the MPI ones (below)
#   scripts/test_sanitizers.sh REGEX     only the ctest tests matching REGEX
# MPI is off in this build: Open MPI's own allocations (never freed before
# exit, by design) would bury real reports, and test_sweep_mpi runs the
# same sweep code as test_sweep. The suppressions are in tests/sanitizers/.
set -euo pipefail
cd "$(dirname "$0")/.."
echo "sanitizers: configuring build-asan/ (ASan + UBSan, -O1 -g)"
mkdir -p build-asan
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFLOWMPM_MPI=OFF \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >build-asan/setup-cmake.log 2>&1 || {
  cat build-asan/setup-cmake.log >&2
  exit 1
}
echo "sanitizers: building with $(nproc) jobs"
cmake --build build-asan -j"$(nproc)"
supp="$PWD/tests/sanitizers"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=0:suppressions=$supp/asan.supp"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$supp/ubsan.supp"
echo "sanitizers: running the suite in build-asan/${1:+ (tests matching $1)}"
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" ${1:+-R "$1"}
