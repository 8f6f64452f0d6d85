# Sourced by the plot scripts that run shipped cases (plot_contact.sh,
# plot_axisymmetric.sh) with their arguments FLOWMPM RUNS_DIR [PNG_DIR]:
# sets bin, runs, root, png (default docs/), threads (THREADS, default 1),
# configs and data (a scratch folder, removed on exit), and defines run.
script=$(basename "$0")
usage="usage: $script FLOWMPM RUNS_DIR [PNG_DIR]"
bin=${1:?$usage}
runs=${2:?$usage}
root=$(cd "$(dirname "$0")/.." && pwd)
png=${3:-$root/docs}
threads=${THREADS:-1}
configs=$root/configs
mkdir -p "$runs" "$png"
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT

# run NAME CASE [--set KEY=VALUE ...]: runs CASE into RUNS_DIR/NAME unless done.
run() {
  local name=$1 case=$2
  shift 2
  local out=$runs/$name
  if grep -qs '"status": "completed"' "$out/summary.json"; then
    return
  fi
  rm -rf "$out"
  echo "${script%.sh}: running $name" >&2
  "$bin" run "$case" --threads "$threads" --quiet --output "$out" "$@"
}
