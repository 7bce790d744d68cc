#!/bin/bash
# Stops the cluster of slurm_up.sh DIR: SIGKILL to unshare kills the namespace, jobs included.
D=$(realpath -m "$1"); P=$(cat "$D/unshare.pid")
C=$(cat /proc/$P/task/$P/children 2>/dev/null)
kill -KILL "$P" 2>/dev/null
for i in $(seq 100); do { [ -z "$C" ] || ! kill -0 $C 2>/dev/null; } && exit 0; sleep 0.05; done
echo "namespace init $C still alive" >&2; exit 1
