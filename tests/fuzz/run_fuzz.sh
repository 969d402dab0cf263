#!/usr/bin/env bash
# run_fuzz.sh SOURCE_DIR TARGET SECONDS OUT_DIR - a short, bounded libFuzzer run of one parser.
#
# TARGET is scene (common/scene/scene.c through scene_parse_string), cli (common/platform/cli.c through
# cli_parse), script (common/platform/input_script.c through input_script_parse) or model
# (common/scene/mesh_data.c through mesh_data_load_memory, Assimp included).
# The target is compiled here with clang (-fsanitize=fuzzer,address,undefined), so any build tree can
# run this test. Steps: replay tests/fuzz/regressions/TARGET/ and the seed corpus (each must pass),
# then fuzz for SECONDS starting from a copy of the seeds. A crash is saved in OUT_DIR as
# crash-<sha1>; copy it into tests/fuzz/regressions/TARGET/ once it is fixed, so it is replayed forever.
# Exit 77 (skipped) when clang or its libFuzzer runtime is missing.
set -u
if [ $# -ne 4 ]; then
    echo "usage: $0 SOURCE_DIR scene|cli|script|model SECONDS OUT_DIR" >&2
    exit 2
fi
src=$1 target=$2 seconds=$3 out=$4
fuzz=$src/tests/fuzz
case $target in
    scene | model) # the scene parser reads glTF files (the model directive), so both need the model code
        sources="$src/common/scene/scene.c $src/common/scene/scene_parser.c $src/common/scene/scene_directives.c $src/common/scene/scene_materials.c $src/common/scene/scene_lights.c $src/common/scene/scene_model.c $src/common/scene/model_import.c $src/common/scene/model_image.c $src/common/scene/mesh_data.c $src/common/scene/mesh_tangents.c $src/common/model/model_file.c $src/common/model/model_scan.c $src/common/model/model_gltf.c $src/common/model/model_gltf_parts.c $src/common/base/log.c $src/common/base/data_dir.c" ;;
    cli) sources="$src/common/platform/input_script.c $src/common/platform/input.c $src/common/platform/cli.c $src/common/platform/cli_help.c $src/common/base/gbuffer_layout_names.c $src/common/platform/keys.c $src/common/base/log.c $src/common/base/data_dir.c $src/common/base/progress.c $src/common/base/image.c" ;;
    script) sources="$src/common/platform/input_script.c $src/common/platform/input.c $src/common/platform/cli.c $src/common/platform/cli_help.c $src/common/base/gbuffer_layout_names.c $src/common/platform/keys.c $src/common/base/log.c $src/common/base/data_dir.c $src/common/base/progress.c $src/common/base/image.c" ;;
    *) echo "unknown fuzz target '$target'" >&2; exit 2 ;;
esac

libs="-pthread"
case $target in
    scene | model) libs="$libs $(pkg-config --libs assimp stb libcjson)" ;;
    cli | script) libs="$libs $(pkg-config --libs stb)" ;; # common/base/image.c: a script's screenshot format
esac
cc=${FUZZ_CC:-clang}
if ! command -v "$cc" >/dev/null 2>&1; then
    echo "skip: $cc not found (the fuzz targets need clang's libFuzzer)"
    exit 77
fi
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

bin=$work/fuzz_$target
layers=$(for d in "$src"/common/*/; do printf -- '-I%s ' "${d%/}"; done) # every layer folder of common/
probe='int LLVMFuzzerTestOneInput(const char *d, long n) { (void)d; return (int)n * 0; }'
# shellcheck disable=SC2086  # $sources is a list
if ! "$cc" -std=c11 -g -O1 -D_POSIX_C_SOURCE=200809L -fsanitize=fuzzer,address,undefined \
        -fno-sanitize-recover=undefined -fno-omit-frame-pointer $layers \
        $(pkg-config --cflags cglm stb 2>/dev/null) -o "$bin" "$fuzz/fuzz_$target.c" $sources $libs -lm \
        2>"$work/cc.log"; then
    if grep -q "fuzzer" "$work/cc.log" &&
            ! echo "$probe" | "$cc" -x c -fsanitize=fuzzer -o "$work/probe" - 2>/dev/null; then
        echo "skip: $cc has no libFuzzer runtime"
        exit 77
    fi
    echo "FAIL: cannot compile the fuzz target"
    cat "$work/cc.log"
    exit 1
fi

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
# Only Assimp's own leaks are suppressed, each with its reason in the file (none of the course's).
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$fuzz/fuzz.lsan.supp}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

# 1. Every saved crash and every seed runs clean.
shopt -s nullglob
replay=("$fuzz/regressions/$target"/* "$fuzz/corpus_$target"/*)
if [ ${#replay[@]} -eq 0 ]; then
    echo "FAIL: no seeds in $fuzz/corpus_$target"
    exit 1
fi
if ! "$bin" -close_fd_mask=3 "${replay[@]}" >"$work/replay.log" 2>&1; then
    echo "FAIL: a saved input crashes the $target parser again:"
    tail -n 40 "$work/replay.log"
    exit 1
fi
echo "ok   replayed ${#replay[@]} saved inputs"

# 2. A bounded run from the seeds. -close_fd_mask keeps the parser's error lines out of the log;
# libFuzzer still prints its own report and the sanitizers' on a crash.
mkdir -p "$work/corpus"
cp "$fuzz/corpus_$target"/* "$work/corpus/"
# The model target also starts from Debian's glTF 2.0 samples that hold all their bytes (a .glb, or
# a .gltf with data URIs: the target writes one file), its format byte first (fuzz_model.c).
if [ "$target" = model ] && [ -d /usr/share/assimp/models/glTF2 ]; then
    while IFS= read -r -d '' f; do
        case $f in *.glb) byte='\005' ;; *) grep -q '"uri" *: *"[^d]' "$f" && continue; byte='\004' ;; esac
        { printf "$byte"; cat "$f"; } >"$work/corpus/debian_$(basename "$(dirname "$f")")_$(basename "$f")"
    done < <(find /usr/share/assimp/models/glTF2 \( -name '*.glb' -o -name '*.gltf' \) -size -64k -print0)
fi
"$bin" "$work/corpus" -dict="$fuzz/$target.dict" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len="${FUZZ_MAX_LEN:-4096}" -close_fd_mask=3 -print_final_stats=1 -artifact_prefix="$out/" >"$work/fuzz.log" 2>&1
rc=$?
grep -E "^#[0-9]+.*DONE|stat::number_of_executed_units|stat::peak_rss_mb" "$work/fuzz.log"
if [ $rc -ne 0 ]; then
    echo "FAIL: the $target parser crashed (exit $rc); input saved in $out:"
    grep -E "^(==|SUMMARY|.*runtime error|artifact_prefix|Test unit written)" "$work/fuzz.log" | head -n 20
    tail -n 40 "$work/fuzz.log"
    exit 1
fi
echo "ok   fuzzed the $target parser for ${seconds}s without a crash"
