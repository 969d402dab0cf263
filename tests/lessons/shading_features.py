#!/usr/bin/env python3
"""shading_features.py SHADERS_DIR - chapter 00's shading.glsl names no feature a later chapter adds,
and each feature's file is included only where its define is set (shaders/shading_features.glsl,
shaders/light_kinds.glsl), so a program built for a scene without it compiles none of it.
Exit 1 with one line per fault (tests/data/shading_bad holds a tree with each kind)."""
import re
import sys

# Each later chapter's feature: the words its code is known by, its file, and the define that
# brings that file in.
FEATURES = [
    ("09 spot lights", ["spot", "cos_inner", "cos_outer", "smoothstep", "LIGHT_SPOT"], "light_spot.glsl", "LIGHT_SPOT"),
    ("14 shadows", ["shadow", "SHADOWS", "atlas"], "shadows.glsl", "SHADOWS"),
    ("15 light buffer", ["LUMINANCE", "shade_light_terms", "LIGHT_PREPASS"], "light_prepass.glsl", None),
    ("17 ambient occlusion", ["AMBIENT_OCCLUSION", "u_ao", "ssao", "ambient_occlusion"],
     "ambient_occlusion.glsl", "AMBIENT_OCCLUSION"),
    ("18 metallic-roughness", ["pbr", "metallic", "roughness", "ggx", "fresnel", "MATERIAL_PBR", "PI"],
     "material_pbr.glsl", "MATERIAL_PBR"),
    ("18 material maps", ["u_maps", "MATERIAL_MAPS", "emissive", "material_apply_maps"], "material_maps.glsl", None),
    ("19 image-based light", ["ibl", "probe", "IMAGE_BASED_LIGHT"], "ibl.glsl", "IMAGE_BASED_LIGHT"),
]


def code_of(text):
    """The text without its comments: what the compiler reads."""
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def names_in(code, word):
    """Whether an identifier of `code` is `word` or contains it as a part (snake case, any case)."""
    for ident in re.findall(r"[A-Za-z_][A-Za-z0-9_]*", code):
        if ident == word or word.lower() in [p.lower() for p in ident.split("_")] or \
                (len(word) > 3 and word.lower() in ident.lower()):
            return True
    return False


def includes_under(text, name):
    """The preprocessor conditions (#ifdef/#if defined NAME stack) around each #include of name."""
    stack, found = [], []
    for line in text.splitlines():
        s = line.strip()
        m = re.match(r"#\s*(ifdef|ifndef|if)\s+(.*)", s)
        if m:
            stack.append((m.group(1), m.group(2)))
        elif re.match(r"#\s*else", s) and stack:
            kind, cond = stack.pop()
            stack.append(("else-of-" + kind, cond))
        elif re.match(r"#\s*endif", s) and stack:
            stack.pop()
        elif re.match(r'#\s*include\s+"%s"' % re.escape(name), s):
            found.append(list(stack))
    return found


def check(shaders):
    faults = []
    shading = code_of(open(f"{shaders}/shading.glsl").read())
    for chapter, words, _, _ in FEATURES:
        for w in words:
            if names_in(shading, w):
                faults.append(f"shading.glsl names '{w}', chapter {chapter}'s: it belongs in that chapter's file")
    for chapter, _, file, define in FEATURES:
        if define is None:
            continue
        sites = []
        for registry in ("shading_features.glsl", "light_kinds.glsl", "shading.glsl"):
            try:
                text = open(f"{shaders}/{registry}").read()
            except OSError:
                continue
            sites += [(registry, conds) for conds in includes_under(text, file)]
        if not sites:
            faults.append(f"{file} (chapter {chapter}) is included by none of the shading files")
        for registry, conds in sites:
            if ("ifdef", define) not in conds and not any(c[0] == "if" and f"defined({define})" in c[1] for c in conds):
                faults.append(f"{registry} includes {file} outside '#ifdef {define}'")
    return faults


if __name__ == "__main__":
    faults = check(sys.argv[1])
    for f in faults:
        print("FAIL", f)
    if not faults:
        print("ok: shading.glsl names no later chapter's feature; each feature's file comes in under its define")
    sys.exit(1 if faults else 0)
