#!/bin/sh
# make demo: run the pipeline on the embedded data and leave pictures in
# results/: importance maps (thesis Fig. 6.1), threshold matrices (ch. 3),
# and Forced Random Sampling of the maps (ch. 4-5), drawn as stipples;
# a 3-D sampling of a volume, drawn as projections.
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

echo "demo: Forced Random Sampling with the default matrix, rendered"
"$BIN/frs-sample" -i blob -n 4096 -v -o "$out/blob.pts"
"$BIN/pts-render" -i blob "$out/blob.pts" -o "$out/blob-samples.png"
"$BIN/frs-sample" -i "$out/sunset-importance.exr" -n 8192 --jitter random \
    -o "$out/sunset.pts"
"$BIN/pts-render" -i "$out/sunset-importance.exr" --log -s 1024x512 \
    "$out/sunset.pts" -o "$out/sunset-samples.png"
echo "demo: sunset.exr before and after: the thesis's window (plain: a lattice"
echo "demo: in the dark), shuffled tiles (white noise) and levels (the default)"
for t in plain shuffled levels; do
	"$BIN/frs-sample" -q -i data/sunset.exr --equirect -n 16384 --tiles $t \
	    -o "$out/sunset-$t.pts"
	"$BIN/pts-render" -i data/sunset.exr --equirect --log -s 1024x512 \
	    "$out/sunset-$t.pts" -o "$out/sunset-tiles-$t.png"
done
"$BIN/frs-sample" -i data/sunset.exr --equirect -n 16384 -v -o /dev/null 2>&1 |
    grep -e level | sed 's/^frs-sample:/demo:/'
"$BIN/frs-sample" -i aniso -n 2048 -o "$out/aniso.pts"
"$BIN/pts-render" -i aniso "$out/aniso.pts" -o "$out/aniso-samples.png"
"$BIN/frs-sample" -i blob --progressive 256,1024,4096 -o "$out/progressive.pts"
"$BIN/pts-render" --color "$out/progressive.pts" -o "$out/progressive.png"

echo "demo: 3-D Forced Random Sampling of a spherical shell (data/default3.frd)"
"$BIN/frs-sample" -i shell3 -n 4096 --sigma 4 --jitter random -v \
    -o "$out/shell3.pts"
"$BIN/pts-render" --axes xy "$out/shell3.pts" -o "$out/shell3-xy.png"
"$BIN/pts-render" --axes xz "$out/shell3.pts" -o "$out/shell3-xz.png"

echo "demo: pictures in $out/:"
ls "$out" | sed 's/^/demo:   /'
