#!/usr/bin/env bash
# The real clients read flowmpm's results right (ctest: readers_*):
#   readers_check.sh paraview FLOWMPM SOURCE_DIR   ParaView's pvpython, both XDMF readers (pv_check.py)
#   readers_check.sh h5py FLOWMPM SOURCE_DIR       h5py, rows and metadata of results.h5 (h5py_check.py)
# on a 2D run with shear whose particles are re-sorted (configs/hard/impact_2d.toml, 512 particles)
# and a 3D run with all six stress components (configs/materials/orthotropic_poplar_offaxis.toml,
# 8 particles). Exits 77 (ctest: skipped) only where the client is not installed, and says so.
set -euo pipefail
client=$1 flowmpm=$2 source=$3

case $client in
  paraview)
    if ! command -v pvpython >/dev/null; then
      echo "SKIPPED: pvpython not found (Debian's python3-paraview; scripts/setup.sh installs it)"
      exit 77
    fi
    check() { pvpython "$source/tests/pv_check.py" "$@"; } ;;
  h5py)
    python=
    for p in /usr/bin/python3 python3; do
      if "$p" -c "import h5py" 2>/dev/null; then python=$p; break; fi
    done
    if [[ -z $python ]]; then
      echo "SKIPPED: no python3 with h5py (Debian's python3-h5py; scripts/setup.sh installs it)"
      exit 77
    fi
    check() { "$python" "$source/tests/h5py_check.py" "$@"; } ;;
  *) echo "unknown client $client" >&2; exit 2 ;;
esac

dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$flowmpm" run "$source/configs/hard/impact_2d.toml" --output "$dir/2d" --threads 2 --quiet
"$flowmpm" run "$source/configs/materials/orthotropic_poplar_offaxis.toml" --output "$dir/3d" --threads 2 --quiet
check "$dir/2d/results.xdmf" 512 2
check "$dir/3d/results.xdmf" 8 3
