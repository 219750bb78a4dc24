#!/bin/bash
# Runs the cases of docs/measurements.md's "The engine" with one `sa` build and writes its
# JSON reports to OUT/<case>.json; bench/compare_reports.py compares two such folders.
# usage: bench/engine_comparison.sh path/to/sa OUT [DATA]
set -u
SA=$1; O=$2; D=${3:-../shared/data}; mkdir -p "$O"
run() { name=$1; shift; timeout 300 "$SA" "$@" --force --quiet --report "$O/$name.json" > "$O/$name.out" 2>&1; echo "$name exit $?"; }
for c in cube stgc-2d stgc-3d param2d sea-2d; do
    ext=node; case $c in stgc-2d|param2d|sea-2d) ext=obj ;; esac
    run map-$c map --rest $D/tlc/$c/input --out $O/map-$c.$ext --no-png
    run map-$c-uv map --rest $D/tlc/$c/input --out $O/map-$c-uv.$ext --until-valid --no-png
    run map-$c-full map --rest $D/tlc/$c/input --out $O/map-$c-full.$ext --variant full --mode full --no-png
    run map-$c-vsa map --rest $D/tlc/$c/input --out $O/map-$c-vsa.$ext --variant vertex --mode full --no-png
    run map-$c-novs map --rest $D/tlc/$c/input --out $O/map-$c-novs.$ext --no-vertex-stage --mode full --no-png
done
run param-camel-ob param --mesh $D/param/camel_b.obj --optimal-bound --out $O/param-camel-ob.obj --no-png
run param-camel-inj param --mesh $D/param/camel_b.obj --free-boundary-injective --out $O/param-camel-inj.obj --no-png
run param-lion-inj param --mesh $D/param/lion.off --free-boundary-injective --out $O/param-lion-inj.obj --no-png
run param-face-ob param --mesh $D/param/face.obj --optimal-bound --out $O/param-face-ob.obj --no-png
run param-hand param --mesh $D/param/hand-uv.obj --out $O/param-hand.obj --no-png
run seam-inspired seamless --mesh $D/frame-fields/inspired_mesh.obj --field $D/frame-fields/inspired_mesh.dmat --out $O/seam-inspired.obj --no-png
run seam-3holes seamless --mesh $D/surfaces/3holes.off --out $O/seam-3holes.obj --no-png
run seam-cow seamless --mesh $D/surfaces/cow.off --out $O/seam-cow.obj --no-png
