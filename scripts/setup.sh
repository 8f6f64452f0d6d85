#!/usr/bin/env bash
# Sets up flowmpm on a Debian machine: installs the Debian packages that are
# missing and builds in build/ (Release).
#   scripts/setup.sh           the program only (build/flowmpm) and the Python
#                              package's needs (numpy, h5py)
#   scripts/setup.sh --tests   also what the test suite needs (ParaView's
#                              pvpython, matplotlib, OpenMPI), and builds everything
# Prints one line per stage and the build's progress; the package manager's
# own output is kept in build/setup-apt.log.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(python3 cmake g++ make ninja-build git libtbb-dev libeigen3-dev libhdf5-dev hdf5-tools libspdlog-dev
          doctest-dev libtomlplusplus-dev libcli11-dev gnuplot-nox python3-numpy python3-h5py)
target=(--target flowmpm)
mpi=()
if [[ ${1:-} == --tests ]]; then
  # matplotlib: the test of the Python package's speed-against-error plot.
  packages+=(python3-paraview python3-matplotlib libopenmpi-dev openmpi-bin)
  target=()
  # The suite tests flowmpm sweep --mpi. A build/ configured by the program's
  # setup, before OpenMPI was installed, has cached that MPI is missing:
  # forget what it found and search again.
  mpi=(-DFLOWMPM_MPI=ON)
  grep -q '^FLOWMPM_MPI:BOOL=OFF' build/CMakeCache.txt 2>/dev/null && mpi+=(-U 'MPI_*')
elif [[ $# -gt 0 ]]; then
  echo "usage: $0 [--tests]" >&2
  exit 1
fi

missing=()
for p in "${packages[@]}"; do
  if [[ $p == python3 ]] && command -v python3 >/dev/null; then continue; fi
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
mkdir -p build
if ((${#missing[@]})); then
  echo "setup: installing ${#missing[@]} Debian package(s): ${missing[*]} (log: build/setup-apt.log)"
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq >build/setup-apt.log 2>&1
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >>build/setup-apt.log 2>&1 || {
    echo "setup: apt-get failed; the last lines of build/setup-apt.log:" >&2
    tail -20 build/setup-apt.log >&2
    exit 1
  }
  echo "setup: packages installed"
else
  echo "setup: all ${#packages[@]} Debian packages present"
fi

# The Python package python/flowmpm: importable by Debian's python3 from any
# directory, through a .pth file in the user's site-packages that names
# this checkout's python/ (docs/guide/python.md).
if [[ -x /usr/bin/python3 ]]; then
  site=$(/usr/bin/python3 -m site --user-site)
  if [[ $(cat "$site/flowmpm.pth" 2>/dev/null) != "$PWD/python" ]]; then
    mkdir -p "$site" && echo "$PWD/python" >"$site/flowmpm.pth"
    echo "setup: python3 imports flowmpm from $PWD/python ($site/flowmpm.pth)"
  fi
fi

# Ninja starts each file as soon as a core is free, where make finishes
# every library of a layer before it starts the next layer's files (about a
# minute of the program's build on 2 cores). A build/ made before keeps
# the generator it was made with.
generator=()
[[ -f build/CMakeCache.txt ]] || generator=(-G Ninja)
echo "setup: configuring build/ (Release)"
cmake -S . -B build "${generator[@]}" "${mpi[@]}" -DCMAKE_BUILD_TYPE=Release >build/setup-cmake.log 2>&1 || {
  cat build/setup-cmake.log >&2
  exit 1
}
echo "setup: building ${target[*]:-everything} with $(nproc) jobs"
cmake --build build -j"$(nproc)" "${target[@]}"
