#!/usr/bin/env bash
# Regenerates README's pictures from the catalog with the koppel executable given (default
# build/tools/koppel): the transfer functions of seed 000 and the coupler curve of seed 003 with
# its straight-line stretch, the tolerance band of seed 000 (koppel plot --tolerance), and the animated cycle of seed 003 (README's GIF; the test
# animate_gif compares it with a fresh one frame by frame). With --check DIR, writes them to DIR instead (the test
# `gallery_current` compares them with the committed ones).
set -euo pipefail
root="$(cd "$(dirname "$0")/../../.." && pwd)"
koppel="${1:-$root/build/tools/koppel}"
out="$root/tools/plot/gallery"
if [ "${2:-}" = "--check" ]; then out="$3"; fi
"$koppel" plot "$root/catalog/entries/slider-crank-offset.yaml" --transfer s --order 2 -o "$out/transfer-slider-crank-offset.svg"
"$koppel" plot "$root/catalog/entries/mzc-crank-rocker.yaml" --curve K --straight --at 180 -o "$out/coupler-curve-mzc-crank-rocker.svg"
"$koppel" plot "$root/catalog/entries/slider-crank-offset.yaml" --tolerance s --tol l1=0.01 --tol l2=0.02 --tol e=0.005 --clearance A=0.003 --from 0 --to 360 --step 5 --samples 1000 --seed 1 -o "$out/tolerance-slider-crank-offset.svg"
"$koppel" animate "$root/catalog/entries/mzc-crank-rocker.yaml" --frames 36 --size 480x360 --fps 12 -o "$out/cycle-mzc-crank-rocker.gif"
