#!/usr/bin/env bash
# run_frame_clock.sh BINARY: both of frame_timer's clocks work on this context: the GPU timer-query
# path (forced with COURSE_FRAME_CLOCK=gpu; on llvmpipe its figures mean little, but the double-
# buffered queries run without a GL error) and the glFinish path. Each must report the chapter's
# passes with a number each, and name its clock.
set -u
bin=$1
fail=0
for clock in gpu cpu; do
  want=$([ $clock = gpu ] && echo gpu-timer || echo glFinish+monotonic)
  out=$(COURSE_FRAME_CLOCK=$clock "$bin" --headless --size 160x120 --bench --frames 4 --gl-debug 2>&1)
  rc=$?
  if [ $rc -eq 77 ]; then echo "skip: no GL context"; exit 77; fi
  line=$(grep "^bench:" <<<"$out")
  if [ $rc -ne 0 ] || [ -z "$line" ]; then echo "FAIL $clock: exit $rc: $(tail -2 <<<"$out")"; fail=1; continue; fi
  missing=""
  for pass in geometry lighting present; do
    grep -Eq " ${pass}_ms=[0-9]+\.[0-9]+( |$)" <<<"$line" || missing="$missing $pass"
  done
  if [ -n "$missing" ] || ! grep -q " pass_clock=$want" <<<"$line"; then
    echo "FAIL $clock: passes missing:${missing:- none}; line: $line"; fail=1
  else
    echo "ok   $clock: $(grep -o ' geometry_ms=.*' <<<"$line")"
  fi
done
exit $fail
