#!/usr/bin/env bash
# Plots an error norm of a sweep against the wall time of its cases:
#   scripts/plot_sweep.sh SWEEP_DIR ERROR_COLUMN [GROUP_COLUMN ...]
# reads SWEEP_DIR/sweep.csv (written by `flowmpm sweep`) and draws, log-log,
# ERROR_COLUMN against wall_seconds with one line per distinct combination of
# the GROUP_COLUMNs, its points joined in case order (the order of the
# varied keys, e.g. increasing resolution, not of the noisy wall time), into
# SWEEP_DIR/speed_vs_error.png. Lines differ by colour, dash and point
# type. Only completed cases with a positive error and wall time are drawn.
# Needs gnuplot (Debian package gnuplot-nox) and python3, both installed by
# scripts/setup.sh.
set -euo pipefail

if (($# < 2)); then
  echo "usage: $0 SWEEP_DIR ERROR_COLUMN [GROUP_COLUMN ...]" >&2
  exit 1
fi
dir=$1
csv=$dir/sweep.csv
png=$dir/speed_vs_error.png
[[ -f $csv ]] || { echo "plot_sweep: $csv: no such file (run flowmpm sweep first)" >&2; exit 1; }
command -v gnuplot >/dev/null || { echo "plot_sweep: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
terminal=png
gnuplot -e "set terminal pngcairo" 2>/dev/null && terminal=pngcairo

# python3 reads the CSV (quoted fields included) and writes the gnuplot
# script, the data inline as one datablock per line of the plot.
script=$(python3 - "$csv" "$png" "$terminal" "${@:2}" <<'EOF'
import csv, math, sys

csv_file, png, terminal, error, groups = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:]
with open(csv_file, newline="") as f:
    reader = csv.DictReader(f)
    columns = reader.fieldnames or []
    rows = list(reader)
for name in ["wall_seconds", error] + groups:
    if name not in columns:
        sys.exit(f"plot_sweep: {csv_file} has no column '{name}'; its columns: {', '.join(columns)}")

def positive(text):
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) and value > 0 else None

lines, left_out = {}, 0
for row in rows:
    x, y = positive(row["wall_seconds"]), positive(row[error])
    if row["status"] != "completed" or x is None or y is None:
        left_out += 1
        continue
    lines.setdefault(tuple(row[g] for g in groups), []).append((int(row["case"]), x, y))
if left_out:
    print(f"plot_sweep: {left_out} of {len(rows)} rows left out (failed, or no positive {error} "
          "and wall_seconds)", file=sys.stderr)
if not lines:
    sys.exit(f"plot_sweep: no completed case in {csv_file} has a positive {error} and wall_seconds")

def quoted(text):  # a gnuplot single-quoted string
    return "'" + text.replace("'", "''") + "'"

# The key goes below the plot; the image grows with it.
out = [f"set terminal {terminal} size 1000,{600 + 20 * len(lines)}", f"set output {quoted(png)}", "set termoption noenhanced",
       "set logscale xy", "set format x '%g'", "set format y '%g'", "set grid",
       "set key below",
       "set xlabel 'wall time of the step loop (s)'",
       f"set ylabel {quoted('relative RMS error: ' + error + ' (sweep.csv column)')}",
       f"set title {quoted(error + ' error against wall time: ' + csv_file)}"]
plots = []
for i, (key, points) in enumerate(lines.items()):
    out.append(f"$line{i} << EOD")
    out += [f"{x!r} {y!r}" for _, x, y in sorted(points)]
    out.append("EOD")
    title = ", ".join(f"{g}={v}" for g, v in zip(groups, key)) or error
    # 8 colours, then dashed, so that every line differs from every other.
    style = f"linecolor {i % 8 + 1} dashtype {i // 8 + 1} pointtype {i % 13 + 1}"
    plots.append(f"$line{i} using 1:2 with linespoints {style} linewidth 2 pointsize 1.2 title {quoted(title)}")
out.append("plot " + ", \\\n     ".join(plots))
print("\n".join(out))
EOF
)
gnuplot <<<"$script"
echo "$png"
