#!/usr/bin/env python3
"""The project's folders depend one way (docs/architecture.md, "Layers").

Every quoted #include of a source file under include/, lib/, tools/, fuzz/ and python/ is
resolved as the build resolves it (the including file's folder, then lib/, tools/lib/,
include/ and the repository root) to a file, which belongs to a folder of LAYERS (the longest
that holds it). A folder may include its own files and the folders of lower layers only:
folders of one layer include none of each other. Exits 1 and lists every include against the
order, every include that resolves to no file, every source in a folder of no layer and every
folder of LAYERS that does not exist; 0 when there is none.

usage: include_order.py REPOSITORY_ROOT
"""
import pathlib
import re
import sys

# Lowest first. Folders of one layer are siblings: none includes another.
LAYERS = [
    ["include/exactccd"],                        # the public headers: themselves only
    ["lib/numeric", "lib/kinds"],                # shared numerics; the one list of kinds
    ["lib/contact"],                             # the rules: contact (d = 0), feature-pair terms (d > 0)
    ["lib/pipeline"],                            # the protocol: Work, Outcome, Findings, run_stages
    ["lib/exact"],                               # the exact kernels and the exact contact path
    ["lib/filter", "lib/separation", "lib/rigid"],  # the stages: linear contact, minimum separation, rigid motion
    ["lib/questions"],                           # the stage lists of both motion models
    ["lib/api"],                                 # the entry points, validation, the C API
    ["lib/scene"],                               # scenes, broad phase, narrow phase over candidates
    # the tools library (not installed): baselines, file formats, scenes, degeneracy categories
    ["tools/lib/baseline", "tools/lib/io", "tools/lib/degeneracy", "tools/lib/broad_phase",
     "tools/lib/scenes"],
    ["tools/lib/methods", "tools/lib/generators"],  # every method by name; the query generators
    # the programs on top: the command line, benchmarks, fuzz targets and plug-ins, the module
    ["tools/exactccd", "tools/bench", "fuzz", "fuzz/plugins", "fuzz/readers", "python/src"],
]
TREES = ["include", "lib", "tools", "fuzz", "python"]
SEARCH = ["lib", "tools/lib", "include", ".", "tools/exactccd"]  # the include directories, in the build's order
GENERATED = "exactccd/"  # exactccd/version.h is generated into the build's include/exactccd/
SOURCES = (".hpp", ".cpp", ".h")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def folder_of(root, path):
    """The folder of LAYERS holding `path` (the longest), or None."""
    rel = path.relative_to(root).as_posix()
    best = None
    for folders in LAYERS:
        for folder in folders:
            if rel.startswith(folder + "/") and (best is None or len(folder) > len(best)):
                best = folder
    return best


def layer_of(folder):
    return next(level for level, folders in enumerate(LAYERS) if folder in folders)


def resolve(root, path, target):
    for base in [path.parent] + [root / s for s in SEARCH]:
        candidate = (base / target).resolve()
        if candidate.is_file():
            return candidate
    if target.startswith(GENERATED):
        return root / "include" / target
    return None


def include_violations(root, path, folder):
    found = []
    where = path.relative_to(root)
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        match = INCLUDE.match(line)
        if not match:
            continue
        target = resolve(root, path, match.group(1))
        if target is None:
            found.append(f"{where}:{number}: includes \"{match.group(1)}\", which resolves to no file")
            continue
        other = folder_of(root, target)
        if other is None:
            found.append(f"{where}:{number}: includes \"{match.group(1)}\", in no folder of the layers")
        elif other != folder and layer_of(other) >= layer_of(folder):
            relation = "a sibling" if layer_of(other) == layer_of(folder) else "a higher layer"
            found.append(f"{where}:{number}: {folder}/ includes \"{match.group(1)}\" of {relation} ({other}/)")
    return found


def violations(root):
    found = [f"{folder}/: in the layers but missing" for folders in LAYERS for folder in folders
             if not (root / folder).is_dir()]
    for tree in TREES:
        if not (root / tree).is_dir():
            found.append(f"{tree}/: a tree the layers cover, but missing")
            continue
        for path in sorted((root / tree).rglob("*")):
            if path.suffix not in SOURCES:
                continue
            folder = folder_of(root, path)
            if folder is None:
                found.append(f"{path.relative_to(root)}: in no folder of tests/lint/include_order.py's layers")
            else:
                found += include_violations(root, path, folder)
    return found


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    root = pathlib.Path(sys.argv[1]).resolve()
    found = violations(root)
    for v in found:
        print(v)
    if found:
        print(f"{len(found)} problem(s) with the layer order (docs/architecture.md, \"Layers\")")
        return 1
    print("every include of " + ", ".join(t + "/" for t in TREES) + " follows the layer order")
    return 0


if __name__ == "__main__":
    sys.exit(main())
