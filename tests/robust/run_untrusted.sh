#!/usr/bin/env bash
# run_untrusted.sh BIN_DIR CASE - files an attacker names in a scene or on the command line. Each run
# is under `timeout` (a hang fails, it does not stall the suite) and must exit 2 with one line on
# stderr that says where (SCENE:LINE) and what.
#
#   fifo          a named pipe as a material's map, a `mesh NAME file PATH`, a `model PATH`, the
#                 scene itself (scene_check), and a chapter's --scene and --script: refused as
#                 "not a regular file", never opened to wait for a writer
#   map_size      a 179-byte PNG whose header says 25,500 x 25,500 (a 522 KB one decodes to 2.6 GB):
#                 refused from its header, before any decoding, under a 1 GB address-space limit,
#                 by scene_check and by a chapter
#   map_one_file  one image named six ways as a colour map (a.png, ./a.png, .//a.png, sub/../a.png, a
#                 link, its absolute path): one texture, and one more for it as data
#   map_truncated a PNG cut short after its header: the scene reads, a chapter's decode fails with
#                 the map's SCENE:LINE, material and attribute (exit 77 without a GL context)
#   script_frames the 14-byte script `0-999999 key W` (47 minutes of frames): refused when read,
#                 with the limit of input_script.h
set -u
if [ $# -ne 2 ]; then
    echo "usage: $0 BIN_DIR fifo|map_size|map_one_file|map_truncated|script_frames" >&2
    exit 2
fi
bin=$1 case=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
LIMIT_S=60 # only a hang takes this long: each run here takes well under a second

# expect WHAT WANT... -- COMMAND...: exit 2 within LIMIT_S, one line on stderr holding every WANT.
expect() {
    local what=$1 wants=()
    shift
    while [ "$1" != "--" ]; do wants+=("$1"); shift; done
    shift
    timeout "$LIMIT_S" "$@" >"$tmp/out" 2>"$tmp/err"
    local rc=$? why=""
    if [ "$rc" -eq 124 ]; then
        why="still running after ${LIMIT_S} s (a hang)"
    elif [ "$rc" -ne 2 ]; then
        why="exit status $rc, expected 2"
    elif [ "$(wc -l <"$tmp/err")" -ne 1 ]; then
        why="$(wc -l <"$tmp/err") lines on stderr, expected 1"
    else
        for want in "${wants[@]}"; do
            grep -qF -- "$want" "$tmp/err" || why="message does not contain '$want'"
        done
    fi
    if [ -z "$why" ]; then
        pass=$((pass + 1))
        echo "ok   $what: $(cut -c1-200 "$tmp/err")"
    else
        fail=$((fail + 1))
        echo "FAIL $what: $why"
        sed 's/^/    stderr: /' "$tmp/err" | head -n 4 | cut -c1-240
    fi
}

# png PATH WIDTH HEIGHT ROWS: an 8-bit grey PNG whose header says WIDTH x HEIGHT, with ROWS rows of
# data (ROWS < HEIGHT: a small file that declares a large picture).
png() {
    python3 - "$@" <<'EOF'
import struct, sys, zlib
path, w, h, rows = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
pixels = zlib.compress(b"\0" * ((w + 1) * rows), 9)
with open(path, "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0))
            + chunk(b"IDAT", pixels) + chunk(b"IEND", b""))
EOF
}

material="material m pbr base 1 1 1 metallic 0 roughness 0.5"
case $case in
fifo)
    mkfifo "$tmp/pipe.png" "$tmp/pipe.obj" "$tmp/pipe.gltf" "$tmp/pipe.scene" "$tmp/pipe.script"
    printf '# a map that is a named pipe\n%s base_map pipe.png\n' "$material" >"$tmp/map.scene"
    printf '# a mesh file that is a named pipe\n\nmesh m file pipe.obj\n' >"$tmp/mesh.scene"
    printf '# a model that is a named pipe\n\n\nmodel pipe.gltf\n' >"$tmp/model.scene"
    expect "map" "map.scene:2: material 'm' base_map '$tmp/pipe.png': cannot open image: not a regular file" \
        -- "$bin/scene_check" "$tmp/map.scene"
    expect "mesh file" "mesh.scene:3: cannot open model '$tmp/pipe.obj': not a regular file" \
        -- "$bin/scene_check" "$tmp/mesh.scene"
    expect "model" "model.scene:4: cannot open model '$tmp/pipe.gltf': not a regular file" \
        -- "$bin/scene_check" "$tmp/model.scene"
    expect "scene" "$tmp/pipe.scene: cannot open scene: not a regular file" -- "$bin/scene_check" "$tmp/pipe.scene"
    expect "--scene" "cannot open scene: not a regular file" \
        -- env -u DISPLAY "$bin/00_forward" --headless --frames 1 --scene "$tmp/pipe.scene"
    expect "--script" "cannot open script: not a regular file" \
        -- env -u DISPLAY "$bin/00_forward" --headless --frames 1 --script "$tmp/pipe.script"
    # the same map through a chapter: refused while the scene is read, before any GL
    expect "map, chapter" "map.scene:2: material 'm' base_map '" "cannot open image: not a regular file" \
        -- env -u DISPLAY "$bin/18_pbr_materials" --headless --frames 1 --scene "$tmp/map.scene"
    ;;
map_size)
    command -v python3 >/dev/null || { echo "skip: python3 not found"; exit 77; }
    png "$tmp/huge.png" 25500 25500 4
    printf '# a map whose header declares 650 million texels\n\n%s emissive 1 1 1 emissive_map huge.png\n' \
        "$material" >"$tmp/huge.scene"
    echo "huge.png: $(stat -c %s "$tmp/huge.png") bytes, header 25500 x 25500"
    want=("huge.scene:3: material 'm' emissive_map '$tmp/huge.png': 25500 x 25500 texels, more than 16384 a side")
    # 1 GB of address space: decoding the picture would need 2.6 GB (not in a sanitizer tree, whose
    # AddressSanitizer reserves terabytes of address space up front)
    limit=(bash -c 'ulimit -v 1000000 && exec "$@"' -)
    ldd "$bin/scene_check" | grep -q libasan && limit=()
    expect "scene_check" "${want[@]}" -- "${limit[@]}" "$bin/scene_check" "$tmp/huge.scene"
    expect "chapter" "${want[@]}" -- "${limit[@]}" \
        env -u DISPLAY "$bin/18_pbr_materials" --headless --frames 1 --scene "$tmp/huge.scene"
    # 16384 a side passes, but not many of them: the scene's maps hold at most 2^28 texels together
    png "$tmp/big.png" 16384 16384 1
    {
        echo "# two 16384 x 16384 maps: 2^29 texels"
        echo "$material base_map big.png"
        echo "$material occlusion_map big.png" | sed 's/^material m /material n /'
    } >"$tmp/total.scene"
    expect "total" "total.scene:3: material 'n' occlusion_map '$tmp/big.png': 16384 x 16384 texels: the scene's maps would hold more than 268435456 in all" \
        -- "$bin/scene_check" "$tmp/total.scene"
    ;;
map_one_file)
    command -v python3 >/dev/null || { echo "skip: python3 not found"; exit 77; }
    mkdir -p "$tmp/sub"
    png "$tmp/a.png" 2 2 2
    ln -s a.png "$tmp/link.png"
    {
        n=0
        for spelling in a.png ./a.png .//a.png sub/../a.png link.png "$tmp/a.png"; do
            n=$((n + 1))
            echo "material m$n pbr base 1 1 1 metallic 0 roughness 0.5 base_map $spelling"
        done
        echo "material linear pbr base 1 1 1 metallic 0 roughness 0.5 occlusion_map ./a.png" # data: its own
    } >"$tmp/one.scene"
    timeout "$LIMIT_S" "$bin/scene_check" "$tmp/one.scene" >"$tmp/out" 2>"$tmp/err"
    rc=$?
    if [ "$rc" -eq 0 ] && grep -q " 7 materials, 2 textures;" "$tmp/out"; then
        pass=$((pass + 1))
        echo "ok   six spellings of a.png as a colour map, once as data: 2 textures"
    else
        fail=$((fail + 1))
        echo "FAIL one file under six spellings: exit $rc, expected 7 materials and 2 textures"
        cat "$tmp/out" "$tmp/err" | head -n 4 | cut -c1-240
    fi
    ;;
map_truncated)
    command -v python3 >/dev/null || { echo "skip: python3 not found"; exit 77; }
    png "$tmp/whole.png" 64 64 64
    head -c 60 "$tmp/whole.png" >"$tmp/cut.png" # the signature, IHDR and the start of IDAT
    printf '# a map cut short


material brick pbr base 1 1 1 metallic 0 roughness 0.5 base_map cut.png
' \
        >"$tmp/cut.scene"
    printf 'mesh box cube
object box brick
light position 0 2 2
' >>"$tmp/cut.scene"
    timeout "$LIMIT_S" env -u DISPLAY "$bin/18_pbr_materials" --headless --size 64x48 --frames 1 \
        --scene "$tmp/cut.scene" >/dev/null 2>"$tmp/err"
    if [ $? -eq 77 ]; then
        echo "skip: no GL context"
        exit 77
    fi
    expect "decode" "cut.scene:4: material 'brick' base_map '$tmp/cut.png': cannot read image: " \
        -- env -u DISPLAY "$bin/18_pbr_materials" --headless --size 64x48 --frames 1 --scene "$tmp/cut.scene"
    ;;
script_frames)
    printf '0-999999 key W' >"$tmp/long.script" # 14 bytes, a million frames
    expect "script" "long.script:1: expected FRAME[-LAST] ACTION [ARGS] (frames 0..99999)" \
        -- env -u DISPLAY "$bin/00_forward" --headless --frames 1 --script "$tmp/long.script"
    ;;
*)
    echo "unknown case '$case'" >&2
    exit 2
    ;;
esac
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
