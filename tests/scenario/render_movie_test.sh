#!/usr/bin/env bash
# talus render and talus movie on a short run: the pictures have the asked size and show the
# grains; the movie has one frame per snapshot (ffprobe). Skipped (77) without ffmpeg.
set -u
talus="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
"$talus" run drum --quiet --out "$dir/run" --set particles.count=60 --set simulation.duration=0.2 \
  --set output.snapshot_interval=0.05 --set packing.settle_max_time=0.05 || exit 1
"$talus" render "$dir/run" --color size --frames all --width 640 || exit 1
n=$(ls "$dir/run/pictures"/size_*.png | wc -l)
[ "$n" -eq 5 ] || { echo "expected 5 pictures, got $n"; exit 1; }
"$talus" render "$dir/run" --frames 99 2> "$dir/err.txt" && { echo "a missing frame was accepted"; exit 1; }
grep -q "snapshots 0 to 4" "$dir/err.txt" || { echo "unclear error: $(cat "$dir/err.txt")"; exit 1; }
if ! command -v ffmpeg > /dev/null || ! command -v ffprobe > /dev/null; then
  echo "ffmpeg is not installed: the movie part is skipped"; exit 77
fi
"$talus" movie "$dir/run" --width 640 || exit 1
frames=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames,width \
  -of csv=p=0 "$dir/run/movie.mp4")
[ "$frames" = "640,5" ] || { echo "movie: width,frames = $frames, expected 640,5"; exit 1; }
echo "5 pictures and a 5-frame movie, 640 px wide"
