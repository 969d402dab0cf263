#!/usr/bin/env bash
# run_robust.sh CHAPTER_BIN SOURCE_DIR IMGDIFF - inputs that fail once a GL context exists, and what a
# failed run must leave behind.
#
#   1. model files the scene parser accepts but Assimp rejects or that hold no triangles: every
#      tests/bad/*.scene whose second line is "# expect-at: render" must exit 2 with its "# expect:"
#      text on stderr
#   2. a broken or missing shader (COURSE_SHADER_DIR points at a temporary copy of shaders/): exit 1
#      and the GLSL info log as "shaders/NAME:LINE:", also for a file pulled in by #include
#   3. no GL context at all: exit 77 and one clear line (EGL without a vendor library, OSMesa unable
#      to give 3.3 core because MESA_GL_VERSION_OVERRIDE caps the version)
#   4. nothing lost: a failed run keeps the previous screenshot byte for byte and leaves no temporary
#      file; an unwritable screenshot path fails with a clear message; a golden is never rewritten
#      by the comparison, even when it fails
# Also: --resize-cycle rejects bad values. Exit 77 when this machine cannot make a GL context at all
# (after checking the message for it).
set -u
if [ $# -ne 3 ]; then
    echo "usage: $0 CHAPTER_BIN SOURCE_DIR IMGDIFF" >&2
    exit 2
fi
bin=$1 src=$2 imgdiff=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
small=(--headless --size 64x48 --gl-debug)

ok() { pass=$((pass + 1)); echo "ok   $1"; }
bad() {
    fail=$((fail + 1))
    echo "FAIL $1"
    sed 's/^/    stderr: /' "$tmp/err" | head -n 6 | cut -c1-240
}

# run [VAR=VALUE...] -- ARGS...: run the chapter with extra environment; sets $rc, $tmp/out, $tmp/err.
run() {
    local envs=()
    while [ "$1" != "--" ]; do envs+=("$1"); shift; done
    shift
    env -u DISPLAY -u WAYLAND_DISPLAY "${envs[@]}" "$bin" "$@" >"$tmp/out" 2>"$tmp/err"
    rc=$?
}

# check NAME CODE TEXT: the last run exited with CODE and printed TEXT on stderr.
check() {
    local name=$1 code=$2 want=$3
    if [ "$rc" -ne "$code" ]; then
        bad "$name: exit $rc, expected $code"
    elif ! grep -qF -- "$want" "$tmp/err"; then
        bad "$name: stderr lacks '$want'"
    else
        ok "$name -> $rc"
    fi
}

# no_temp_files NAME DIR: nothing named like image_write_png's temporary file is left in DIR.
no_temp_files() {
    local left
    left=$(find "$2" -name '*.tmp-*' 2>/dev/null | head -n 3)
    if [ -n "$left" ]; then
        bad "$1: temporary file left behind: $left"
    else
        ok "$1: no temporary file left"
    fi
}

# ---- 3. no GL context (first: it is the one check that needs no GL) -------------------------------
no_gl=(__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent MESA_GL_VERSION_OVERRIDE=3.2)
run "${no_gl[@]}" -- "${small[@]}"
check "no GL: EGL and OSMesa both fail" 77 "no GL 3.3 core context could be created (tried EGL and OSMesa)"
run "${no_gl[@]}" -- --headless=osmesa --size 64x48
check "no GL: OSMesa alone fails" 77 "no GL 3.3 core context could be created (tried OSMesa)"
if [ "$(grep -c . "$tmp/err")" -ne 1 ]; then
    bad "no GL: expected one line on stderr"
else
    ok "no GL: one line"
fi

# --resize-cycle's own command-line errors (the rest of the command line is tests/robust/run_cli.sh's).
run -- --headless --resize-cycle -1
check "bad --resize-cycle" 2 "bad --resize-cycle '-1'"
run -- --headless --resize-cycle 5 --bench
check "--resize-cycle with --bench" 2 "--resize-cycle changes the size between timed frames"

run -- "${small[@]}"
if [ "$rc" -eq 77 ]; then
    echo "skip: no GL context on this machine ($pass checks passed before)"
    [ "$fail" -eq 0 ] && exit 77
    exit 1
fi

# ---- 1. model files that fail when they are loaded ----------------------------------------------
found=0
for scene in "$src"/tests/bad/*.scene; do
    [ "$(sed -n 2p "$scene")" = "# expect-at: render" ] || continue
    found=$((found + 1))
    want=$(head -n 1 "$scene")
    want=${want#"# expect: "}
    run -- "${small[@]}" --scene "$scene"
    check "model: $(basename "$scene")" 2 "$want"
done
[ "$found" -ge 4 ] && ok "found $found render-time model cases" || bad "only $found render-time model cases"

# ---- 2. shaders ---------------------------------------------------------------------------------
fresh_shaders() { rm -rf "$tmp/shaders" && cp -r "$src/shaders" "$tmp/shaders"; }
# break FILE LINE: append a token no GLSL compiler accepts to that line.
break_line() { sed -i "$2s/\$/ @@@ broken here/" "$tmp/shaders/$1"; }

fresh_shaders
break_line forward.frag 12
run COURSE_SHADER_DIR="$tmp/shaders" -- "${small[@]}"
check "shader: syntax error in forward.frag" 1 "shaders/forward.frag:12:"

fresh_shaders
line=$(grep -n "^vec3 shade_light\|^vec3 shade_ambient" "$tmp/shaders/shading.glsl" | head -n 1 | cut -d: -f1)
break_line shading.glsl "${line:-5}"
run COURSE_SHADER_DIR="$tmp/shaders" -- "${small[@]}"
check "shader: error inside an #include'd file" 1 "shaders/shading.glsl:${line:-5}:"

fresh_shaders
rm "$tmp/shaders/forward.vert"
run COURSE_SHADER_DIR="$tmp/shaders" -- "${small[@]}"
check "shader: missing forward.vert" 1 "$tmp/shaders/forward.vert: cannot read shader"

fresh_shaders
rm "$tmp/shaders/shading.glsl"
run COURSE_SHADER_DIR="$tmp/shaders" -- "${small[@]}"
check "shader: missing include shading.glsl" 1 "shading.glsl: cannot read shader"

fresh_shaders
sed -i '1s/.*/void main() {}/' "$tmp/shaders/forward.frag"
run COURSE_SHADER_DIR="$tmp/shaders" -- "${small[@]}"
check "shader: no #version line" 1 "shaders/forward.frag:1: the first line must be #version"

# ---- 4. nothing lost ----------------------------------------------------------------------------
mkdir -p "$tmp/keep"
shot=$tmp/keep/shot.png
run -- "${small[@]}" --screenshot "$shot"
check "screenshot written" 0 "wrote $shot"
cp "$shot" "$tmp/shot.orig"

fresh_shaders
break_line forward.frag 12
run COURSE_SHADER_DIR="$tmp/shaders" -- "${small[@]}" --screenshot "$shot" --size 80x60
check "failing run (broken shader) with --screenshot" 1 "shaders/forward.frag:12:"
cmp -s "$shot" "$tmp/shot.orig" && ok "the previous screenshot is intact after a failed run" ||
    bad "the previous screenshot changed after a failed run"
run -- "${small[@]}" --scene "$src/tests/bad/model_unreadable.scene" --screenshot "$shot"
check "failing run (bad model) with --screenshot" 2 "cannot load model"
cmp -s "$shot" "$tmp/shot.orig" && ok "the previous screenshot is intact after a bad model" ||
    bad "the previous screenshot changed after a bad model"
max=$("$bin" --headless --gl-info 2>/dev/null | sed -n 's/.*max_width=\([0-9]*\).*/\1/p')
run -- "${small[@]}" --size "$((${max:-16384} + 1))x16" --screenshot "$shot"
check "failing run (size over the GL limit) with --screenshot" 2 "larger than this GL allows"
cmp -s "$shot" "$tmp/shot.orig" && ok "the previous screenshot is intact after a size error" ||
    bad "the previous screenshot changed after a size error"
no_temp_files "failed runs" "$tmp/keep"

run -- "${small[@]}" --screenshot "$tmp/missing-folder/shot.png"
check "screenshot into a missing folder" 2 \
    "cannot write $tmp/missing-folder/shot.png: No such file or directory"
[ ! -e "$tmp/missing-folder" ] && ok "the missing folder was not created" ||
    bad "the missing folder was created"

mkdir -p "$tmp/adir.png"
echo "keep me" >"$tmp/adir.png/inside.txt"
run -- "${small[@]}" --screenshot "$tmp/adir.png"
check "screenshot path that is a folder" 2 "cannot write $tmp/adir.png"
[ "$(cat "$tmp/adir.png/inside.txt")" = "keep me" ] && ok "the folder's content is intact" ||
    bad "the folder changed"
no_temp_files "rename onto a folder" "$tmp"
run -- "${small[@]}" --screenshot "$tmp/shot.gif"
check "screenshot in a format the course cannot write" 2 "unknown image format"

echo "not a png" >"$tmp/keep/old.png"
run -- "${small[@]}" --screenshot "$tmp/keep/old.png"
check "a successful run replaces an old file" 0 "wrote $tmp/keep/old.png"
magic=$(head -c 4 "$tmp/keep/old.png" | od -An -tx1 | tr -d ' \n')
[ "$magic" = "89504e47" ] && ok "the replaced file is a PNG" || bad "the replaced file is not a PNG ($magic)"
no_temp_files "successful run" "$tmp/keep"

# The golden comparison never writes the golden: a golden of another size fails the comparison and
# must stay as it was.
run -- --headless --size 32x24 --gl-debug --screenshot "$tmp/golden.png"
cp "$tmp/golden.png" "$tmp/golden.orig"
if bash "$src/tests/golden/run_golden.sh" "$imgdiff" "$tmp/golden-out" wrong "$tmp/golden.png" 1 0.0001 \
        -- "$bin" "${small[@]}" >"$tmp/out" 2>"$tmp/err"; then
    bad "run_golden.sh accepted a golden of the wrong size"
elif cmp -s "$tmp/golden.png" "$tmp/golden.orig"; then
    ok "a failing golden comparison leaves the golden untouched"
else
    bad "run_golden.sh rewrote the golden on failure"
fi

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
