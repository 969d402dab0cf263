#!/usr/bin/env bash
# run_tiled_glslang.sh SHADER_DIR: every compute shader (*.comp), with its #includes expanded the
# way the loader expands them (common/renderers.c, renderer_compute_program_load) and the constants
# of shader_layout.h injected, must pass glslangValidator at its own
# #version (4.30: compute shaders are core since OpenGL 4.3). tests/run_glslang.sh checks the
# vertex and fragment shaders at 3.30.
set -u
dir=$1
command -v glslangValidator >/dev/null || { echo "skip: glslangValidator missing (package glslang-tools)"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
expand() { # FILE DEPTH
  local file=$1 depth=$2 line
  [ "$depth" -gt 4 ] && { echo "includes nested too deeply in $file" >&2; return 1; }
  while IFS= read -r line || [ -n "$line" ]; do
    if [[ $line =~ ^[[:space:]]*#include[[:space:]]+\"([^\"]+)\" ]]; then
      [ -f "$dir/${BASH_REMATCH[1]}" ] || { echo "$file: missing include ${BASH_REMATCH[1]}" >&2; return 1; }
      expand "$dir/${BASH_REMATCH[1]}" $((depth + 1)) || return 1
    else
      printf '%s\n' "$line"
    fi
  done <"$file"
}
defines=$(sed -n 's/^ *X(\([A-Z_]*\), *\([0-9-]*\)).*/#define SHADER_\1 \2/p' "$dir/../common/shader_layout.h")
pass=0 fail=0
for f in "$dir"/*.comp; do
  [ -f "$f" ] || continue
  name=$(basename "$f")
  expand "$f" 0 >"$tmp/x" || { fail=$((fail + 1)); echo "FAIL $name"; continue; }
  { head -n 1 "$tmp/x"; printf '%s\n' "$defines"; tail -n +2 "$tmp/x"; } >"$tmp/$name"
  if ! head -1 "$tmp/$name" | grep -q '^#version 430 core'; then
    fail=$((fail + 1)); echo "FAIL $name: first line must be '#version 430 core'"; continue
  fi
  if out=$(glslangValidator -S comp "$tmp/$name" 2>&1); then
    pass=$((pass + 1)); echo "ok   $name"
  else
    fail=$((fail + 1)); echo "FAIL $name"; echo "$out"
  fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
