# Shared by the scale-out scripts (sourced): a single-process reference render, and the checks
# that chunks rendered elsewhere add up to it. Expects $tumble, $scene, $work and $size set.

skip() {
  echo "SKIPPED: $*"
  exit 77   # CTest's SKIP_RETURN_CODE for these tests
}

fail() {
  echo "FAILED: $*" >&2
  exit 1
}

# The motion once, and every frame rendered by one process that simulates for itself; sets
# $frames to the clip's frame count.
simulate_and_render_reference() {
  "$tumble" simulate "$scene" -q --trajectory "$work/motion.csv"
  "$tumble" render "$scene" -q --size "$size" -o "$work/reference/f_####.png"
  frames=$(find "$work/reference" -name 'f_*.png' | wc -l)
  [ "$frames" -gt 4 ] || fail "the reference render holds $frames frames"
}

# Every frame present once, each PNG byte for byte the reference's.
check_pngs() {
  local dir=$1 count k name
  count=$(find "$dir" -maxdepth 1 -name 'f_*.png' | wc -l)
  [ "$count" -eq "$frames" ] || fail "$dir holds $count frames, not $frames"
  for ((k = 1; k <= frames; ++k)); do
    printf -v name 'f_%04d.png' "$k"
    cmp -s "$work/reference/$name" "$dir/$name" || fail "$dir/$name differs from the single-process render"
  done
  echo "ok: $frames frames in $dir, each bit-identical to the single-process render"
}

# The joined video as ffprobe reads it: H.264, every frame, one frame interval apart from 0.
check_video() {
  local video=$1 summary count
  summary=$(ffprobe -v error -count_frames -select_streams v:0 \
    -show_entries stream=codec_name,nb_read_frames,r_frame_rate -of csv=p=0 "$video") ||
    fail "ffprobe cannot read $video"
  [ "$summary" = "h264,30/1,$frames" ] || fail "$video: ffprobe says '$summary', expected 'h264,30/1,$frames'"
  count=$(ffprobe -v error -select_streams v:0 -show_entries frame=pts_time -of csv=p=0 "$video" |
    awk -F, -v n="$frames" '$1 == "" { next }   # side-data lines
      { k++; if ($1 + 0 < (k - 1) / 30 - 1e-6 || $1 + 0 > (k - 1) / 30 + 1e-6) bad = 1 }
      END { print (bad || k != n) ? "bad" : k }')
  [ "$count" = "$frames" ] || fail "$video: frame times are not 0, 1/30 s, 2/30 s, ..."
  echo "ok: $video holds $frames H.264 frames at 1/30 s intervals"
}
