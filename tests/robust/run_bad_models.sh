#!/usr/bin/env bash
# run_bad_models.sh SCENE_CHECK_BIN SOURCE_DIR course|assimp [mesh|model] - every bad model file is
# refused cleanly.
#
# Reads tests/bad/models.expect (mesh, the default: a line `mesh m file PATH`) or tests/bad/gltf.expect
# (model: a line `model PATH`, glTF 2.0 through the model directive); their headers say the format.
# For each file of the chosen set, a one-line scene naming it goes through scene_check, which builds
# the meshes: the run must exit 2
# with exactly one line on stderr holding "cannot load model 'PATH': " and the expected text, that
# line printable ASCII and Assimp's quoted part at most 163 characters (model_file.h:
# MODEL_QUOTE_MAX, and "..."); no signal, no sanitizer report. "ok: ..." lines must load (exit 0)
# and print what follows "ok: " (mesh: "mesh m: N triangles,", model: in the summary line).
# `assimp` also checks that every file under invalid/ and every broken glTF 2.0 sample is listed
# (model: every .gltf and .glb under glTF2/), and exits 77 (skipped) when assimp-testmodels is not
# installed.
# In the asan tree the same runs under AddressSanitizer + LeakSanitizer (label sanitize).
set -u
if [ $# -ne 3 ] && [ $# -ne 4 ]; then
    echo "usage: $0 SCENE_CHECK_BIN SOURCE_DIR course|assimp [mesh|model]" >&2
    exit 2
fi
bin=$1 src=$(cd "$2" && pwd) set=$3 directive=${4:-mesh}
models=/usr/share/assimp/models
expect_file=$src/tests/bad/models.expect
[ "$directive" = model ] && expect_file=$src/tests/bad/gltf.expect
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [ "$set" = assimp ] && [ ! -d "$models/invalid" ]; then
    echo "skip: assimp-testmodels is not installed ($models/invalid; scripts/install-deps.sh installs it)"
    exit 77
fi

pass=0 fail=0
listed="$tmp/listed"
: >"$listed"
while IFS= read -r line; do
    case $line in "#"* | "") continue ;; esac
    where=${line%% | *} want=${line#* | }
    case $where in
        course:*) [ "$set" = course ] || continue; path=$src/tests/bad/models/${where#course:} ;;
        assimp:*) [ "$set" = assimp ] || continue; path=$models/${where#assimp:} ;;
        *) echo "FAIL bad line in models.expect: $line"; fail=$((fail + 1)); continue ;;
    esac
    echo "$path" >>"$listed"
    if [ ! -f "$path" ]; then
        echo "FAIL $where: no such file"; fail=$((fail + 1)); continue
    fi
    if [ "$directive" = model ]; then
        printf 'model %s\n' "$path" >"$tmp/one.scene"
    else
        printf 'mesh m file %s\nmaterial r albedo 1 1 1\nobject m r\n' "$path" >"$tmp/one.scene"
    fi
    timeout 120 "$bin" "$tmp/one.scene" >"$tmp/out" 2>"$tmp/err" # 124: it hung (Assimp can loop for ever)
    rc=$?
    why=""
    case $want in
        "ok: "*)
            [ "$rc" -eq 0 ] || why="exit $rc, expected 0"
            got="mesh m: ${want#ok: },"
            [ "$directive" = model ] && got="${want#ok: };"
            [ -n "$why" ] || grep -qF "$got" "$tmp/out" || why="stdout lacks '$got'"
            ;;
        *)
            msg=$(grep -F "cannot load model '$path': " "$tmp/err" | head -n 1)
            quoted=${msg#*"cannot load model '$path': "}
            if [ "$rc" -ne 2 ]; then why="exit $rc, expected 2"
            elif [ "$(wc -l <"$tmp/err")" -ne 1 ]; then why="$(wc -l <"$tmp/err") lines on stderr, expected 1"
            elif [ -z "$msg" ]; then why="no 'cannot load model' line"
            elif ! grep -qF -- "$want" <<<"$quoted"; then why="message lacks '$want'"
            elif LC_ALL=C grep -q '[^[:print:]]' "$tmp/err"; then why="a byte that is not printable ASCII"
            elif [ "${#quoted}" -gt 400 ]; then why="message of ${#quoted} characters"
            fi
            ;;
    esac
    if [ -z "$why" ]; then
        pass=$((pass + 1)); echo "ok   $where"
    else
        fail=$((fail + 1)); echo "FAIL $where: $why"; head -c 600 "$tmp/err" | sed 's/^/    stderr: /'
    fi
done <"$expect_file"

if [ "$set" = assimp ] && [ "$directive" = model ]; then
    # Nothing forgotten: every glTF 2.0 file of the package.
    while IFS= read -r f; do
        grep -qxF "$f" "$listed" || { fail=$((fail + 1)); echo "FAIL $f is not in tests/bad/gltf.expect"; }
    done < <(find "$models/glTF2" -name '*.gltf' -o -name '*.glb' | sort)
elif [ "$set" = assimp ]; then
    # Nothing forgotten: the whole invalid/ folder, and the broken glTF 2.0 samples.
    for f in "$models"/invalid/* "$models"/OFF/invalid.off \
             "$models"/glTF2/{BoxBadNormals-glTF-Binary,BoxWithInfinites-glTF-Binary,IncorrectVertexArrays,IndexOutOfRange,MissingBin,RecursiveNodes,SchemaFailures,TestNoRootNode,wrongTypes}/*.{gltf,glb}; do
        [ -f "$f" ] || continue
        grep -qxF "$f" "$listed" || { fail=$((fail + 1)); echo "FAIL $f is not in tests/bad/models.expect"; }
    done
fi
echo "$pass passed, $fail failed"
[ "$pass" -gt 0 ] && [ "$fail" -eq 0 ]
