#!/usr/bin/env bash
# A flowmpm sweep as a Slurm job array: each task of the array runs one
# shard of the cases (`flowmpm sweep --shard I/N`, the cases whose number
# is I modulo N); run without an array, the script collects sweep.csv from
# the cases' folders (`flowmpm sweep --collect`). Submit both, the second
# after the first has ended:
#
#   job=$(sbatch --parsable --array=0-7 docs/slurm_sweep.sh SWEEP.toml)
#   sbatch --dependency=afterany:$job docs/slurm_sweep.sh SWEEP.toml
#
# --array must be a plain range (0-7, or 1-8; a %limit is fine, a :step is
# not): its N tasks are the N shards. Extra arguments go to flowmpm (e.g.
# --output DIR; give the same to both). The output directory must be on a
# file system that every node sees. FLOWMPM names the program (default:
# flowmpm on PATH). A task's exit status is flowmpm's: 2 if one of its
# cases failed (recorded in its folder; the others went on). Resubmitting
# the array skips the cases already completed and runs the failed and
# missing ones again. README.md "Sweeps beyond one machine".
#
#SBATCH --job-name=flowmpm-sweep
#SBATCH --nodes=1
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=16
#SBATCH --time=04:00:00
#SBATCH --output=flowmpm-sweep-%A_%a.out
set -euo pipefail

if (($# < 1)); then
  echo "usage: sbatch --array=0-(N-1) $0 SWEEP.toml [flowmpm sweep options]   (one shard per task)" >&2
  echo "       sbatch --dependency=afterany:JOB $0 SWEEP.toml [options]      (collect sweep.csv)" >&2
  exit 1
fi
flowmpm=${FLOWMPM:-flowmpm}

if [[ -n ${SLURM_ARRAY_TASK_ID:-} ]]; then
  shard=$((SLURM_ARRAY_TASK_ID - ${SLURM_ARRAY_TASK_MIN:-0}))/$SLURM_ARRAY_TASK_COUNT
  # The threads Slurm gave the task (flowmpm's default, all the cores it may
  # use, is the same where Slurm confines the task to its cores).
  threads=()
  [[ -n ${SLURM_CPUS_PER_TASK:-} ]] && threads=(--threads "$SLURM_CPUS_PER_TASK")
  exec "$flowmpm" sweep "$@" --shard "$shard" "${threads[@]}"
else
  exec "$flowmpm" sweep "$@" --collect
fi
