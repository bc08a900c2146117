#!/bin/bash
# GNU parallel as the scheduler: four local jobs render the knock-down in four chunks from one
# trajectory, as PNGs and as video parts; the parts are joined. Checks every frame is there once,
# bit-identical to a single-process render, and the joined video has every frame (ffprobe).
# Usage: parallel_local_test.sh TUMBLE_BINARY SOURCE_DIR. Exit 77 (skipped) without parallel or ffprobe.
set -euo pipefail
tumble=$(realpath "$1")
scene=$(realpath "$2")/scenes/knockdown.json
size=320x180
. "$(dirname "$0")/chunk_checks.sh"
command -v parallel >/dev/null || skip "GNU parallel is not installed (apt-get install parallel)"
command -v ffprobe >/dev/null || skip "ffprobe is not installed (apt-get install ffmpeg)"
work=$(mktemp -d "${TMPDIR:-/tmp}/tumble-parallel.XXXXXX")
trap 'rm -rf "$work"' EXIT

simulate_and_render_reference
parallel -j4 --halt now,fail=1 "$tumble" render "$scene" -q --size "$size" --from-trajectory "$work/motion.csv" \
  --shard {}/4 -o "$work/chunks/f_####.png" ::: 1 2 3 4
check_pngs "$work/chunks"
parallel -j4 --halt now,fail=1 "$tumble" render "$scene" -q --size "$size" --from-trajectory "$work/motion.csv" \
  --shard {}/4 -o "$work/clip.mp4" ::: 1 2 3 4
"$tumble" join -q "$work/clip.mp4" "$work"/clip.part-*-of-0004.mp4
check_video "$work/clip.mp4"
