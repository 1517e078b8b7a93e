#!/bin/sh
# make demo: run the pipeline on the embedded data and leave pictures in
# results/.  So far: the importance maps that the samplers will use
# (thesis Fig. 6.1) and threshold matrices (ch. 3).
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

echo "demo: a 256x256 Forced Random Dithering matrix and its quality"
"$BIN/frd-gen" -s 256 -q -o "$out/M256.frd"
"$BIN/frd-gen" --quality "$out/M256.frd" | sed 's/^/demo:   /'
echo "demo: the shipped default matrix data/default.frd (2048x2048)"
"$BIN/frd-gen" --quality data/default.frd | sed 's/^/demo:   /'

echo "demo: pictures in $out/:"
ls "$out" | sed 's/^/demo:   /'
