#!/usr/bin/env bash
# Sets up, builds and runs the shipped default case: the uniaxial stress
# benchmark (CB-Geo mpm-benchmarks), Case I, with USF, USL and MUSL, then prints the
# table of results at t = 0.1 s against the analytical solution.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
echo "running the three cases (logs in results/uniaxial_case1_*/run.log)"
for scheme in usf usl musl; do
  build/flowmpm run "configs/uniaxial_stress/case1_${scheme}.toml" --quiet
done
python3 - <<'PY'
import json
print("Uniaxial stress, Case I, t = 0.1 s; analytical: "
      "eps_yy = -0.001, eps_xx = 0.0002, sigma_yy = -1 Pa, sigma_xx = 0")
print(f"{'scheme':8}{'eps_yy':>12}{'eps_xx':>12}{'sigma_yy':>12}{'sigma_xx':>12}{'Mpsteps/s':>11}")
for scheme in ("usf", "usl", "musl"):
    s = json.load(open(f"results/uniaxial_case1_{scheme}/summary.json"))
    b = s["bodies"][0]
    print(f"{s['scheme']:8}{b['mean_strain']['yy']:12.6g}{b['mean_strain']['xx']:12.6g}"
          f"{b['mean_stress']['yy']:12.6g}{b['mean_stress']['xx']:12.6g}"
          f"{s['particle_steps_per_second'] / 1e6:11.3g}")
print("results (HDF5 + XDMF for ParaView, CSV, JSON) in results/uniaxial_case1_*/")
PY
