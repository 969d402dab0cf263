#!/usr/bin/env bash
# run_plateau.sh IMAGE_LEVELS LEVEL MIN_FRACTION OUT.png COMMAND...: render COMMAND's screenshot and
# check that it clips at LEVEL with at least MIN_FRACTION of its lit pixels there (tools/image_levels.c).
set -u
levels=$1 level=$2 fraction=$3 out=$4
shift 4
mkdir -p "$(dirname "$out")"
rm -f "$out"
"$@" --screenshot "$out"
rc=$?
if [ $rc -eq 77 ]; then echo "skip: no GL context"; exit 77; fi
if [ $rc -ne 0 ]; then echo "FAIL: '$*' exited with $rc"; exit 1; fi
"$levels" --plateau "$level" --min-fraction "$fraction" "$out"
