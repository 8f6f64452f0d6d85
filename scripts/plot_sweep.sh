#!/usr/bin/env bash
# Plots an error norm of a sweep against the wall time of its cases:
#   scripts/plot_sweep.sh [--front COLUMN] SWEEP_DIR ERROR_COLUMN [COLOUR_COLUMN [MARKER_COLUMN [DASH_COLUMN]]]
# reads SWEEP_DIR/sweep.csv (written by `flowmpm sweep`) and draws, log-log,
# ERROR_COLUMN against wall_seconds with one line per distinct combination of
# the grouping columns, its points joined in case order (the order of the
# varied keys, e.g. increasing resolution, not of the noisy wall time), into
# SWEEP_DIR/speed_vs_error.png. The first grouping column sets the colour
# (a shape function keeps its colour in every plot: linear blue, uGIMP
# orange, B-spline 2 green, B-spline 3 red), the second the marker (a
# scheme keeps its marker: USF circle, USL square, MUSL triangle), a third
# the dash. The legend has one entry per colour and one per marker, not
# one per line; the title names the sweep (the folder's name) and the
# error. Only completed cases with a positive error and wall time are
# drawn. --front COLUMN adds, per value of COLUMN (e.g.
# analysis.velocity_update), its Pareto front: the cases of that value that
# no faster case of it beats in error (the least error each wall time
# buys), a thick pale line, and prints the front's cases with their
# particle-steps per second. Needs gnuplot (Debian package gnuplot-nox) and python3, both
# installed by scripts/setup.sh.
set -euo pipefail

front=""
if [[ ${1:-} == --front ]]; then
  front=${2:?"--front needs a column"}
  shift 2
fi
if (($# < 2)); then
  echo "usage: $0 [--front COLUMN] SWEEP_DIR ERROR_COLUMN [COLOUR_COLUMN [MARKER_COLUMN [DASH_COLUMN]]]" >&2
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
script=$(python3 - "$csv" "$png" "$terminal" "$front" "${@:2}" <<'EOF'
import csv, math, os, sys

csv_file, png, terminal, front = sys.argv[1:5]
error, groups = sys.argv[5], sys.argv[6:]
with open(csv_file, newline="") as f:
    reader = csv.DictReader(f)
    columns = reader.fieldnames or []
    rows = list(reader)
for name in ["wall_seconds", error] + groups + ([front, "particle_steps_per_second"] if front else []):
    if name not in columns:
        sys.exit(f"plot_sweep: {csv_file} has no column '{name}'; its columns: {', '.join(columns)}")

def positive(text):
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) and value > 0 else None

lines, left_out, by_front = {}, 0, {}
for row in rows:
    x, y = positive(row["wall_seconds"]), positive(row[error])
    if row["status"] != "completed" or x is None or y is None:
        left_out += 1
        continue
    lines.setdefault(tuple(row[g] for g in groups), []).append((int(row["case"]), x, y))
    if front:
        by_front.setdefault(row[front], []).append((x, y, row))
if left_out:
    print(f"plot_sweep: {left_out} of {len(rows)} rows left out (failed, or no positive {error} "
          "and wall_seconds)", file=sys.stderr)
if not lines:
    sys.exit(f"plot_sweep: no completed case in {csv_file} has a positive {error} and wall_seconds")

if len(groups) > 3:
    sys.exit("plot_sweep: at most three grouping columns (colour, marker, dash)")

def quoted(text):  # a gnuplot single-quoted string
    return "'" + text.replace("'", "''") + "'"

# Fixed styles for the values the engine knows, so that a shape function has
# the same colour and a scheme the same marker in every plot.
COLOURS = {"linear": "#1f77b4", "gimp": "#ff7f0e", "bspline2": "#2ca02c", "bspline3": "#d62728"}
PALETTE = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"]
MARKERS = {"usf": 7, "usl": 5, "musl": 9}  # filled circle, square, triangle
MARKER_LIST = [7, 5, 9, 11, 13, 15, 4, 6]
LABELS = {"linear": "linear", "gimp": "uGIMP", "bspline2": "B-spline 2", "bspline3": "B-spline 3",
          "usf": "USF", "usl": "USL", "musl": "MUSL", "flip": "FLIP", "pic": "PIC", "blend": "blend",
          "apic": "APIC", "xpic": "XPIC"}
NAMES = {"analysis.shape_function": "shape function", "analysis.scheme": "scheme",
         "analysis.velocity_update": "velocity update"}

def values_of(k):  # the distinct values of grouping column k, in case order
    seen = []
    for key in lines:
        if key[k] not in seen:
            seen.append(key[k])
    return seen

def colour(value, k):
    return COLOURS.get(value) or PALETTE[values_of(k).index(value) % len(PALETTE)]

def marker(value, k):
    return MARKERS.get(value) or MARKER_LIST[values_of(k).index(value) % len(MARKER_LIST)]

def label(value):
    return LABELS.get(value, value)

sweep = os.path.basename(os.path.normpath(os.path.dirname(os.path.abspath(csv_file))))
out = [f"set terminal {terminal} size 1000,650", f"set output {quoted(png)}", "set termoption noenhanced",
       "set logscale xy", "set format x '%g'", "set format y '%g'", "set grid",
       "set key outside right top vertical Left reverse samplen 2 spacing 1.2",
       "set xlabel 'wall time of the step loop (s)'",
       f"set ylabel {quoted('relative RMS error: ' + error)}",
       f"set title {quoted(sweep + ': ' + error + ' error against wall time')}"]
plots = []
# Pareto fronts first, under the cases: per value, the cases in order of
# wall time that lower the least error seen so far.
FRONT_COLOURS = ["#7f7f7f", "#9467bd", "#8c564b", "#e377c2", "#17becf", "#bcbd22"]
for j, (value, points) in enumerate(by_front.items()):
    best, kept = math.inf, []
    for x, y, row in sorted(points, key=lambda p: p[0]):
        if y < best:
            best = y
            kept.append((x, y, row))
    print(f"# front {front} = {value}: wall_seconds {error} particle_steps_per_second case", file=sys.stderr)
    for x, y, row in kept:
        print(f"#   {x:.4g} {y:.3g} {float(row['particle_steps_per_second']):.3g} "
              + " ".join(f"{g}={row[g]}" for g in groups + ["grid.cell_size"] if g != front and g in row),
              file=sys.stderr)
    out.append(f"$front{j} << EOD")
    out += [f"{x!r} {y!r}" for x, y, _ in kept]
    out.append("EOD")
    plots.append(f"$front{j} using 1:2 with steps linecolor rgb {quoted(FRONT_COLOURS[j % len(FRONT_COLOURS)])} "
                 f"linewidth 9 title {quoted('front: ' + label(value))}")
for i, (key, points) in enumerate(lines.items()):
    out.append(f"$line{i} << EOD")
    out += [f"{x!r} {y!r}" for _, x, y in sorted(points)]
    out.append("EOD")
    style = f"linecolor rgb {quoted(colour(key[0], 0)) if groups else quoted(PALETTE[0])}"
    style += f" pointtype {marker(key[1], 1) if len(groups) > 1 else 7}"
    style += f" dashtype {values_of(2).index(key[2]) + 1 if len(groups) > 2 else 1}"
    plots.append(f"$line{i} using 1:2 with linespoints {style} linewidth 2 pointsize 1.3 notitle")
# The legend: one entry per colour, per marker, per dash, under the grouping
# column's name.
for k, name in enumerate(groups):
    plots.append(f"keyentry with lines linecolor rgb '#ffffff' title {quoted(NAMES.get(name, name) + ':')}")
    for value in values_of(k):
        if k == 0:
            style = f"with lines linecolor rgb {quoted(colour(value, 0))} linewidth 3"
        elif k == 1:
            style = f"with points linecolor rgb 'black' pointtype {marker(value, 1)} pointsize 1.3"
        else:
            style = f"with lines linecolor rgb 'black' dashtype {values_of(2).index(value) + 1} linewidth 2"
        plots.append(f"keyentry {style} title {quoted(label(value))}")
out.append("plot " + ", \\\n     ".join(plots))
print("\n".join(out))
EOF
)
gnuplot <<<"$script"
echo "$png"
