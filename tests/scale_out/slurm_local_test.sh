#!/bin/bash
# A real Slurm as the scheduler: starts munged, then a one-node slurmctld and slurmd from a
# slurm.conf written into a temporary folder (node at 127.0.0.1 with this machine's cores,
# proctrack/linuxproc, task/none, no accounting, free ports), submits docs/scale-out/render.sbatch
# as two job arrays of four tasks (PNG frames, and video parts) rendering the knock-down from one
# trajectory, waits, joins the video and checks: every frame present once, each PNG bit-identical
# to a single-process render, the joined video's frame count and times (ffprobe). Stops every
# daemon it started, by the pid it started.
# Usage: slurm_local_test.sh TUMBLE_BINARY SOURCE_DIR. Exit 77 (skipped) where Slurm, munge or
# ffprobe is not installed, or when not root (slurmd must be).
set -euo pipefail
tumble=$(realpath "$1")
source_dir=$(realpath "$2")
scene=$source_dir/scenes/knockdown.json
size=320x180
. "$(dirname "$0")/chunk_checks.sh"
for tool in munged mungekey slurmctld slurmd sbatch sinfo ffprobe; do
  command -v "$tool" >/dev/null || skip "$tool is not installed (apt-get install slurm-wlm munge ffmpeg)"
done
[ "$(id -u)" -eq 0 ] || skip "slurmd runs jobs as their user, so it must start as root"

work=$(mktemp -d "${TMPDIR:-/tmp}/tumble-slurm.XXXXXX")
pids=()
stop_daemons() {
  local pid
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  rm -rf "$work"
}
trap stop_daemons EXIT

free_port() {
  python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

# munge: its own key, socket and files, so it disturbs no munged already running.
mkdir -p "$work/munge" "$work/state" "$work/spool" "$work/logs"
chmod 700 "$work/munge"
mungekey --create --keyfile="$work/munge/munge.key"
munged --foreground --force --key-file="$work/munge/munge.key" --socket="$work/munge/munge.socket" \
  --pid-file="$work/munge/munged.pid" --seed-file="$work/munge/munged.seed" \
  --log-file="$work/munge/munged.log" 2>>"$work/munge/munged.log" &
pids+=($!)

host=$(hostname -s)
cat > "$work/slurm.conf" <<CONF
ClusterName=tumble
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge/munge.socket
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
NodeName=render1 NodeAddr=127.0.0.1 NodeHostname=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=render Nodes=render1 Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf
slurmctld -D -i -f "$SLURM_CONF" 2>>"$work/slurmctld.log" &
pids+=($!)
slurmd -D -N render1 -f "$SLURM_CONF" 2>>"$work/slurmd.log" &
pids+=($!)
for ((i = 0; ; ++i)); do
  state=$(sinfo -h -n render1 -o %T 2>/dev/null || true)
  [ "$state" = idle ] && break
  if ((i == 60)); then
    tail -n 5 "$work/munge/munged.log" "$work/slurmctld.log" "$work/slurmd.log" >&2
    fail "the one-node Slurm did not come up in 30 s (node state '${state}')"
  fi
  sleep 0.5
done
echo "ok: one-node Slurm up (node render1, $(nproc) CPUs)"

simulate_and_render_reference
export TUMBLE=$tumble SCENE=$scene TRAJECTORY=$work/motion.csv TUMBLE_FLAGS="--size $size"
submit() {   # OUTPUT: the array's -o; waits for every task and fails if one did
  OUTPUT=$1 sbatch --wait --array=1-4 --chdir="$work" --output="$work/logs/%x-%A_%a.log" \
    --job-name="$2" "$source_dir/docs/scale-out/render.sbatch" >/dev/null
}
submit "$work/chunks/f_####.png" frames &
frames_job=$!
submit "$work/clip.mp4" video &
video_job=$!
wait "$frames_job" || { cat "$work"/logs/* >&2; fail "the PNG array failed"; }
wait "$video_job" || { cat "$work"/logs/* >&2; fail "the video array failed"; }
for i in 1 2 3 4; do
  grep -q "chunk $i of 4 (SLURM_ARRAY_TASK_ID=$i (array 1-4))" "$work"/logs/frames-*_"$i".log ||
    fail "array task $i did not report chunk $i of 4"
done
check_pngs "$work/chunks"
"$tumble" join -q "$work/clip.mp4" "$work"/clip.part-*-of-0004.mp4
check_video "$work/clip.mp4"
