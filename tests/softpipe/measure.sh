#!/usr/bin/env bash
# measure.sh BUILD TEST...: what a softpipe bound is measured from (tests/softpipe/softpipe.cmake).
# For each TEST (golden.NAME or agree.NAME) whose softpipe run left its pictures in
# BUILD/test-out/softpipe (run it first: ctest --test-dir BUILD -C softpipe -R '^softpipe\.TEST$'),
# the pixels over each tolerance and the largest difference, against the golden (tests/golden/NAME.png)
# or between the two renderings:
#   golden.14_shadows: >0 14830 >1 1379 >2 1199 ... >64 4  max=104 at (131,139)
set -u
build=$1
shift
root=$(cd "$(dirname "$0")/../.." && pwd)
imgdiff=$build/bin/imgdiff out=$build/test-out/softpipe
status=0
for test in "$@"; do
  case $test in
    golden.*) name=${test#golden.} a=$root/tests/golden/$name.png b=$out/$name.png ;;
    agree.*) name=${test#agree.} a=$out/$name.a.png b=$out/$name.b.png ;;
    *) echo "measure.sh: '$test' is neither golden.NAME nor agree.NAME" >&2; status=2; continue ;;
  esac
  if [ ! -f "$a" ] || [ ! -f "$b" ]; then
    echo "measure.sh: no pictures for $test in $out (run softpipe.$test first)" >&2
    status=2
    continue
  fi
  line="" last=""
  for tol in 0 1 2 3 4 5 6 7 8 16 32 64; do
    last=$("$imgdiff" --tolerance "$tol" --max-fraction 1 "$a" "$b")
    line+=" >$tol $(sed -n 's/.*over_tol=\([0-9]*\).*/\1/p' <<<"$last")"
  done
  echo "$test:$line  $(grep -o 'max=[0-9]* at ([0-9]*,[0-9]*)' <<<"$last")"
done
exit $status
