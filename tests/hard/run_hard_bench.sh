#!/usr/bin/env bash
# run_hard_bench.sh BINARY SCENE: case 1 seen from the command line. The chapter's --bench line must
# report the dim light as culled (culled_lights=1, active_lights=1), and with --cutoff 0 nothing
# is culled (culled_lights=0, active_lights=2).
set -u
bin=$1 scene=$2
fail=0
check() { # check ARGS_DESCRIPTION EXPECTED_ACTIVE EXPECTED_CULLED -- ARGS...
  local what=$1 active=$2 culled=$3
  shift 4
  local line
  line=$("$bin" --headless --size 64x48 --frames 1 --warmup 0 --bench --gl-debug \
    --scene "$scene" "$@" 2>/dev/null)
  local rc=$?
  if [ $rc -eq 77 ]; then echo "skip: no GL context"; exit 77; fi
  echo "$line"
  if [ $rc -ne 0 ]; then echo "FAIL $what: exit $rc"; fail=1; return; fi
  case "$line" in
    *" active_lights=$active culled_lights=$culled "*) echo "ok   $what: active $active, culled $culled" ;;
    *) echo "FAIL $what: expected active_lights=$active culled_lights=$culled"; fail=1 ;;
  esac
}
check "default cut-off" 1 1 --
check "cut-off 0" 2 0 -- --cutoff 0
exit $fail
