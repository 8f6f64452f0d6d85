#!/usr/bin/env bash
# Installs the Debian packages flowmpm needs (only those missing; quiet when
# all are present) and builds it in build/ (Release).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(python3 cmake g++ make libtbb-dev libeigen3-dev libhdf5-dev hdf5-tools libspdlog-dev
          doctest-dev libtomlplusplus-dev libcli11-dev gnuplot-nox libopenmpi-dev openmpi-bin)
missing=()
for p in "${packages[@]}"; do
  if [[ $p == python3 ]] && command -v python3 >/dev/null; then continue; fi
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
