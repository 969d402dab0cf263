#!/usr/bin/python3
"""check_layers.py - common/ is built in layers, each folder including only its own and lower ones.

    check_layers.py ROOT    exit 1, naming each file and include, when the layout is broken

The layers, lowest first (a folder of common/ each; a file may include its own layer's headers and
those of every layer below it, never one above):
    base      log, images, the data folder, exit codes, constants shared with GLSL: no GL, no scene
    model     model files read safely: the pre-scan and Assimp's bounded, validated import: no scene
    scene     the scene format, lights and meshes as data: no GL
    gl        the GL layer: helpers, programs, framebuffers, timers, the scene on the GPU
    platform  the window or headless context, input, keys, the command line
    render    the passes chapters share (forward, G-buffer, volumes, present)
    clusters  chapter 11's cluster lists, built on render (Forward+, chapters 12 and 13)
    shadows   chapter 14's shadow plan and depth atlas, built on gl (chapters 15 to 19 cast them too)
    app       the runner every chapter hands itself to: window, overlay, compare, embedding
The checks:
    1. every header named by an #include "..." in common/ is found in common/ (no chapters/, tools/
       or tests/ header: they sit above all layers);
    2. no file includes a header of a higher layer;
    3. no cycle between modules (a module is NAME.c with NAME.h; NAME_internal.h belongs to NAME);
    4. every layer folder is one of the list, and holds at most 12 modules.
"""
import pathlib
import re
import sys

LAYERS = ["base", "model", "scene", "gl", "platform", "render", "clusters", "shadows", "app"]
MAX_MODULES = 12
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def module_of(path):
    name = path.stem
    return name[: -len("_internal")] if name.endswith("_internal") else name


def main(root):
    common = pathlib.Path(root) / "common"
    files = sorted(p for p in common.rglob("*") if p.suffix in (".c", ".h"))
    where = {p.name: p.parent.name for p in files}
    problems = []
    for folder in sorted({p.parent for p in files}):
        if folder.parent != common or folder.name not in LAYERS:
            problems.append(f"{folder.relative_to(root)}: not a layer folder ({', '.join(LAYERS)})")
        modules = {module_of(p) for p in folder.iterdir() if p.suffix in (".c", ".h")}
        if len(modules) > MAX_MODULES:
            problems.append(f"{folder.relative_to(root)}: {len(modules)} modules, more than {MAX_MODULES}")
    edges = {}
    for p in files:
        layer = p.parent.name
        for name in INCLUDE.findall(p.read_text()):
            if name not in where:
                problems.append(f"{p.relative_to(root)}: includes \"{name}\", which is not in common/")
                continue
            target = where[name]
            if target in LAYERS and layer in LAYERS and LAYERS.index(target) > LAYERS.index(layer):
                problems.append(f"{p.relative_to(root)} ({layer}) includes {name} of the higher layer {target}")
            a, b = module_of(p), module_of(pathlib.Path(name))
            if a != b:
                edges.setdefault(a, set()).add(b)
    problems += [f"include cycle: {' -> '.join(c)}" for c in cycles(edges)]
    for line in problems:
        print("FAIL " + line)
    if not problems:
        print(f"ok   {len(files)} files in {len(LAYERS)} layers: every include points down or sideways, no cycle")
    return 1 if problems else 0


def cycles(edges):
    """One cycle per strongly connected group of modules that reach each other."""
    found, state = [], {}

    def visit(node, path):
        state[node] = "open"
        for nxt in sorted(edges.get(node, ())):
            if state.get(nxt) == "open":
                found.append(path[path.index(nxt):] + [nxt])
            elif nxt not in state:
                visit(nxt, path + [nxt])
        state[node] = "done"

    for node in sorted(edges):
        if node not in state:
            visit(node, [node])
    return found


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: check_layers.py ROOT")
    sys.exit(main(sys.argv[1]))
