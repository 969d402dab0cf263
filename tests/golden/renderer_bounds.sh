# renderer_bounds.sh - sourced by run_golden.sh and run_agreement.sh: a bound may be written
# "LLVMPIPE,OTHER" (e.g. tolerance "1,3", fraction "0.0001,0.0002"). llvmpipe keeps the first, the
# course's strict bound; any other renderer gets the second, a bound measured on that hardware and
# stated beside the test. A plain number applies everywhere.

# bound_for VALUE BINARY: the value for the renderer BINARY gets (asked with --gl-info, once).
bound_for() {
  local value=$1 bin=$2
  case $value in *,*) ;; *) echo "$value"; return ;; esac
  if [ -z "${COURSE_RENDERER:-}" ]; then
    COURSE_RENDERER=$("$bin" --headless --gl-info 2>/dev/null | sed -n 's/^gl: renderer=//p')
  fi
  case $COURSE_RENDERER in
    *llvmpipe*|"") echo "${value%%,*}" ;;
    *) echo "${value#*,}" ;;
  esac
}
