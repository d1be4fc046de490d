#!/usr/bin/env bash
# Fails when README's pictures are not what the koppel executable given draws now
# (regenerate them with tools/plot/gallery/make.sh).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
fresh="$(mktemp -d)"
trap 'rm -rf "$fresh"' EXIT
bash "$here/make.sh" "$1" --check "$fresh"
status=0
for f in "$fresh"/*.svg; do
  if ! cmp -s "$f" "$here/$(basename "$f")"; then
    echo "tools/plot/gallery/$(basename "$f") is out of date: run tools/plot/gallery/make.sh" >&2
    status=1
  fi
done
exit $status
