#!/usr/bin/env bash
# A flowmpm sweep as a Slurm job array: each task of the array runs one
# shard of the cases (`flowmpm sweep --shard I/N`, the cases whose number
# is I modulo N); run without an array, the script collects sweep.csv from
# the cases' folders (`flowmpm sweep --collect`). Submit both, the second
# after the first has ended, from the login node:
#
#   cpus=4   # CPUs per task: what one shard may use (docs/guide/cluster.md)
#   job=$(sbatch --parsable --array=0-7 --cpus-per-task=$cpus docs/slurm_sweep.sh SWEEP.toml)
#   sbatch --dependency=afterany:$job --cpus-per-task=1 --output=flowmpm-sweep-%j-collect.out docs/slurm_sweep.sh SWEEP.toml
#
# or let the script submit both (the same two commands, printed as run):
#
#   CPUS_PER_TASK=4 docs/slurm_sweep.sh --submit 8 SWEEP.toml
#
# --array must be a plain range (0-7, or 1-8; a %limit is fine, a :step is
# not): its N tasks are the N shards. Each task asks for --cpus-per-task
# CPUs (default 4, the #SBATCH line below, which all but the smallest nodes
# have; a task asking for more CPUs than a node has never starts) and runs
# its shard on that many threads; the collect job computes nothing and
# needs one. Array tasks log to flowmpm-sweep-JOB_TASK.out; give the
# collect job its own --output (a job outside an array has no task number:
# %a would print 4294967294). Extra arguments go to flowmpm (e.g.
# --output DIR; give the same to both). The output directory must be on a
# file system that every node sees. FLOWMPM names the program (default:
# flowmpm on PATH). A task's exit status is flowmpm's: 2 if one of its
# cases failed (recorded in its folder; the others went on). Resubmitting
# the array skips the cases already completed and runs the failed and
# missing ones again. docs/guide/cluster.md.
#
#SBATCH --job-name=flowmpm-sweep
#SBATCH --nodes=1
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=4
#SBATCH --time=04:00:00
#SBATCH --output=flowmpm-sweep-%A_%a.out
set -euo pipefail

usage() {
  echo "usage: sbatch --array=0-(N-1) [--cpus-per-task=C] $0 SWEEP.toml [flowmpm sweep options]   (one shard per task)" >&2
  echo "       sbatch --dependency=afterany:JOB --output=NAME.out $0 SWEEP.toml [options]         (collect sweep.csv)" >&2
  echo "       [CPUS_PER_TASK=C] $0 --submit N SWEEP.toml [options]                                (submit both)" >&2
  exit 1
}
(($# >= 1)) || usage
flowmpm=${FLOWMPM:-flowmpm}

if [[ $1 == --submit ]]; then
  # From the login node: the array of N shards, then the collect job after it.
  (($# >= 3)) && [[ $2 =~ ^[1-9][0-9]*$ ]] || usage
  shards=$2
  shift 2
  cpus=${CPUS_PER_TASK:-4}
  [[ $cpus =~ ^[1-9][0-9]*$ ]] || { echo "$0: CPUS_PER_TASK must be a positive whole number, got '$cpus'" >&2; exit 1; }
  array=(sbatch --parsable --array="0-$((shards - 1))" --cpus-per-task="$cpus" --output=flowmpm-sweep-%A_%a.out "$0" "$@")
  echo "${array[*]}"
  job=$("${array[@]}")
  job=${job%%;*}  # --parsable prints JOB or JOB;CLUSTER
  echo "$job"
  collect=(sbatch --dependency="afterany:$job" --cpus-per-task=1 --output=flowmpm-sweep-%j-collect.out "$0" "$@")
  echo "${collect[*]}"
  exec "${collect[@]}"
fi

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
