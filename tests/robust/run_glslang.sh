#!/usr/bin/env bash
# run_glslang.sh SHADER_DIR: every shader (.vert, .frag, .comp), with its #includes expanded and
# shader_layout.h's constants injected the way common/gl/gl_program.c does, must pass glslangValidator at
# the course's versions: GLSL 3.30 for vertex and fragment shaders (the course's minimum), 4.30 for
# compute shaders (core since OpenGL 4.3). Each is checked in every variant the loader can build:
#   - a shader with a line "// variants: A | B | ..." in every variant listed there (each: "NAME
#     VALUE" pairs separated by commas, or "-" for no defines), and in no other;
#   - any other shader without defines, then with each macro it tests with #ifdef or defined()
#     defined to 1 on its own, and with each value of shader_layout.h that an "#if NAME == ..."
#     compares it with; a macro named on a line "// fragment only: NAME ..." of an included file
#     (it reads gl_FragCoord) is tried in fragment shaders only.
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

# shader_layout.h's constants, as common/gl/gl_program.c injects them after the #version line.
layout=$(sed -n 's/^ *X(\([A-Z_]*\), *\([0-9-]*\)).*/#define SHADER_\1 \2/p' "$dir/../common/base/shader_layout.h")
[ -n "$layout" ] || { echo "no constants found in common/base/shader_layout.h"; exit 1; }

variants() { # FILE EXPANDED STAGE: one variant per line, its defines as "NAME VALUE;NAME VALUE" ("" = none)
  local listed skip
  skip=$([ "$3" = frag ] || sed -n 's|^// fragment only: *||p' "$2" | tr ' ,' '\n\n' | sed '/^$/d')
  listed=$(sed -n 's|^// variants: *||p' "$1" | head -n 1)
  if [ -n "$listed" ]; then
    tr '|' '\n' <<<"$listed" | sed 's/^ *//; s/ *$//; s/ *, */;/g; s/^-$//'
    return
  fi
  echo ""
  grep -oE '#ifdef +[A-Z_]+|defined\( *[A-Z_]+ *\)' "$2" | grep -oE '[A-Z_]{2,}' | grep -v '_GLSL$' |
    grep -vxF -e "${skip:-_}" | sort -u | sed 's/$/ 1/'
  grep -oE '#(el)?if +[A-Z_]+ *== *SHADER_[A-Z_]+' "$2" | sed -E 's/#(el)?if +([A-Z_]+) *== *(SHADER_[A-Z_]+)/\2 \3/' |
    sort -u
}

pass=0 fail=0
for f in "$dir"/*.vert "$dir"/*.frag "$dir"/*.comp; do
  [ -f "$f" ] || continue
  name=$(basename "$f")
  stage=${name##*.}
  want='#version 330 core'
  [ "$stage" = comp ] && want='#version 430 core'
  if ! expand "$f" 0 > "$tmp/$name.expanded"; then
    fail=$((fail + 1)); echo "FAIL $name"; continue
  fi
  if ! head -1 "$tmp/$name.expanded" | grep -qx "$want"; then
    fail=$((fail + 1)); echo "FAIL $name: first line must be '$want'"; continue
  fi
  while IFS= read -r variant; do
    defines=$(tr ';' '\n' <<<"$variant" | sed '/^$/d; s/^/#define /')
    { head -n 1 "$tmp/$name.expanded"; printf '%s\n' "$layout"; [ -n "$defines" ] && printf '%s\n' "$defines"
      tail -n +2 "$tmp/$name.expanded"; } > "$tmp/$name"
    label="$name${variant:+ [$variant]}"
    if out=$(glslangValidator -S "$stage" "$tmp/$name" 2>&1); then
      pass=$((pass + 1)); echo "ok   $label"
    else
      fail=$((fail + 1)); echo "FAIL $label"; echo "$out"
    fi
  done < <(variants "$f" "$tmp/$name.expanded" "$stage")
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
