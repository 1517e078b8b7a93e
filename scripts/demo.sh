#!/bin/sh
# make demo: run the pipeline on the embedded data and leave pictures in
# results/.  Only imap exists so far: the demo makes and shows the
# importance maps that the samplers will use (thesis Fig. 6.1).
set -eu
cd "$(dirname "$0")/.."
BIN=${BIN:-bin}
out=results/demo
mkdir -p "$out"

echo "demo: procedural importance maps (256x256, 16-bit PNG)"
for spec in const blob ramp aniso; do
	"$BIN/imap" gen "$spec" -s 256x256 -o "$out/$spec.png"
done
"$BIN/imap" gen sky -s 512x256 -o "$out/sky.exr"
"$BIN/imap" convert --log "$out/sky.exr" "$out/sky-log.png"

echo "demo: the real environment map data/sunset.exr as importance"
"$BIN/imap" convert --log data/sunset.exr "$out/sunset-radiance-log.png"
"$BIN/imap" convert --equirect -s 256x128 data/sunset.exr "$out/sunset-importance.exr"
"$BIN/imap" convert --log "$out/sunset-importance.exr" "$out/sunset-importance-log.png"
"$BIN/imap" info "$out/sunset-importance.exr" | sed 's/^/demo:   /'

echo "demo: pictures in $out/:"
ls "$out" | sed 's/^/demo:   /'
