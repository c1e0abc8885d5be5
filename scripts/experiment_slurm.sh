#!/usr/bin/env bash
# Scale-out on a Slurm cluster (or any engine that runs numbered tasks): one array task per trial
# of a job list written by `lucent experiment ... --emit-jobs FILE --out DIR`; each task runs line
# $SLURM_ARRAY_TASK_ID (1-based) of FILE, which writes DIR/results/<trial>.json. When all tasks
# are done, `lucent experiment merge DIR` makes the report. DIR must be on a shared file system.
#
# usage:
#   lucent experiment all --seed 0 --out /shared/run1 --emit-jobs /shared/run1/jobs.txt
#   sbatch --array=1-$(wc -l < /shared/run1/jobs.txt) scripts/experiment_slurm.sh /shared/run1/jobs.txt
#   lucent experiment merge /shared/run1
# With GNU parallel on one machine instead: parallel < /shared/run1/jobs.txt
# Several seeds: one directory and job list per seed (the readings of the report are computed
# inside every trial), then one pooled report:
#   for s in 0 1 2 3 4; do lucent experiment all --seed $s --out /shared/seed$s \
#     --emit-jobs /shared/seed$s/jobs.txt; done
#   cat /shared/seed*/jobs.txt > /shared/jobs.txt   # one array over all seeds
#   sbatch --array=1-$(wc -l < /shared/jobs.txt) scripts/experiment_slurm.sh /shared/jobs.txt
#   lucent experiment merge /shared/seed0 /shared/seed1 /shared/seed2 /shared/seed3 \
#     /shared/seed4 --out /shared/seeds
#SBATCH --job-name=lucent-experiment
#SBATCH --cpus-per-task=1
set -euo pipefail
jobs="${1:?usage: experiment_slurm.sh JOBS_FILE}"
line=$(sed -n "${SLURM_ARRAY_TASK_ID:?not a Slurm array task}p" "$jobs")
[ -n "$line" ] || { echo "no line ${SLURM_ARRAY_TASK_ID} in $jobs" >&2; exit 1; }
# RAYON_NUM_THREADS: one core per task, as requested above.
RAYON_NUM_THREADS="${SLURM_CPUS_PER_TASK:-1}" bash -c "$line"
