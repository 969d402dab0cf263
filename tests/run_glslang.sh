#!/usr/bin/env bash
# run_glslang.sh SHADER_DIR: every .vert/.frag, with its #includes expanded the way
# common/gl_util.c expands them, must pass glslangValidator as GLSL 3.30.
set -u
dir=$1
command -v glslangValidator >/dev/null || { echo "skip: glslangValidator missing (package glslang-tools)"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

expand() { # expand FILE DEPTH
  local file=$1 depth=$2 line inc
  [ "$depth" -gt 4 ] && { echo "includes nested too deeply in $file" >&2; return 1; }
  while IFS= read -r line || [ -n "$line" ]; do
    if [[ $line =~ ^[[:space:]]*#include[[:space:]]+\"([^\"]+)\" ]]; then
      inc="${BASH_REMATCH[1]}"
      [ -f "$dir/$inc" ] || { echo "$file: missing include $inc" >&2; return 1; }
      expand "$dir/$inc" $((depth + 1)) || return 1
    else
      printf '%s\n' "$line"
    fi
  done < "$file"
}

# shader_layout.h's constants, as common/gl_util.c injects them after the #version line.
layout=$(sed -n 's/^ *X(\([A-Z_]*\), *\([0-9-]*\)).*/#define SHADER_\1 \2/p' "$dir/../common/shader_layout.h")
[ -n "$layout" ] || { echo "no constants found in common/shader_layout.h"; exit 1; }

pass=0 fail=0
for f in "$dir"/*.vert "$dir"/*.frag; do
  [ -f "$f" ] || continue
  name=$(basename "$f")
  stage=${name##*.}
  if ! expand "$f" 0 > "$tmp/$name.expanded"; then
    fail=$((fail + 1)); echo "FAIL $name"; continue
  fi
  { head -n 1 "$tmp/$name.expanded"; printf '%s\n' "$layout"; tail -n +2 "$tmp/$name.expanded"; } > "$tmp/$name"
  if ! head -1 "$tmp/$name" | grep -q '^#version 330 core'; then
    fail=$((fail + 1)); echo "FAIL $name: first line must be '#version 330 core' (the course's minimum)"; continue
  fi
  if out=$(glslangValidator -S "$stage" "$tmp/$name" 2>&1); then
    pass=$((pass + 1)); echo "ok   $name"
  else
    fail=$((fail + 1)); echo "FAIL $name"; echo "$out"
  fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
