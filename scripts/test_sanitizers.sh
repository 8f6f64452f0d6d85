#!/usr/bin/env bash
# Tests built with AddressSanitizer and UndefinedBehaviorSanitizer (GCC's
# -fsanitize=address,undefined) in build-asan/, apart from the Release
# build in build/. Any report ends the process that made it with a failure
# (halt_on_error), so a report fails its test. scripts/test.sh runs it
# after the Release suite (so CI does); it needs scripts/setup.sh --tests.
#   scripts/test_sanitizers.sh            the subset below
#   scripts/test_sanitizers.sh TEST ...   these test programs instead
# The subset: the tests that drive the flowmpm program over its whole
# surface (the fuzz test, its first 150 of 300 mutated cases, the robustness tests, the
# command line, sweeps, the output writers) and the engine on 1 and 2
# threads (determinism) and in its stages (shape functions, the uniaxial
# benchmark). The engine's kernels are compiled once, into the engine
# library (engine/simulation_instances.cpp.in), so more tests cost little
# to build; running them does: at -O0 with the sanitizers the physics runs
# tens of times slower, and the remaining tests, which run the same stages
# with other materials and cases, run in the Release build only.
# -O0: at -O1 the sanitizer build of flowmpm alone took more than 20
# minutes on 2 cores. docs/testing.md gives the measured times.
# MPI is off here: Open MPI keeps its own allocations until exit by design,
# which LeakSanitizer would report, and test_sweep_mpi runs the sweep code
# that test_sweep covers. tests/sanitizers/ holds the suppressions, each
# with its reason.
set -euo pipefail
cd "$(dirname "$0")/.."
tests=(test_fuzz test_robustness test_cli test_sweep test_output test_determinism test_shape_functions
       test_uniaxial_stress)
if (($#)); then tests=("$@"); fi
echo "sanitizers: configuring build-asan/ (ASan + UBSan, -O0 -g, no MPI)"
mkdir -p build-asan
generator=()
[[ -f build-asan/CMakeCache.txt ]] || generator=(-G Ninja)  # as scripts/setup.sh
cmake -S . -B build-asan "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFLOWMPM_MPI=OFF \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O0 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >build-asan/setup-cmake.log 2>&1 || {
  cat build-asan/setup-cmake.log >&2
  exit 1
}
echo "sanitizers: building flowmpm and ${tests[*]} with $(nproc) jobs"
cmake --build build-asan -j"$(nproc)" --target flowmpm "${tests[@]}"
supp="$PWD/tests/sanitizers"
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$supp/ubsan.supp"
# The fuzz test's first 150 mutants of its 300 (the Release suite runs all):
# at -O0 each run is tens of times slower and the job is CPU-bound.
export FLOWMPM_FUZZ_MUTANTS=150
# Its Ctrl-C after 10 s rather than 2: under the sanitizers a process can
# take more than 2 s to reach main() on a loaded machine (CI saw two killed
# by the signal before their handler was installed).
export FLOWMPM_FUZZ_INTERRUPT_AFTER=10
regex="^($(IFS='|'; echo "${tests[*]}"))(:.*)?\$"  # test_determinism runs as two ctest tests
echo "sanitizers: running ${#tests[@]} test programs under ASan + UBSan"
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -R "$regex"
