#!/usr/bin/env python3
"""The library's folders depend one way (docs/architecture.md, "Layers").

Every quoted #include of a file under lib/ names its folder ("filter/interval_stage.hpp");
a folder may include its own files, the public headers (exactccd/...) and the folders of
lower layers only. Exits 1 and lists every include that goes against the order (or names no
known folder), 0 when there is none.

usage: include_order.py LIB_DIR
"""
import pathlib
import re
import sys

# Lowest first. Folders of one layer are siblings: none includes another.
LAYERS = [
    ["numeric", "kinds"],                # shared numerics; the one list of kinds
    ["contact"],                         # the rules: contact (d = 0), feature-pair terms (d > 0)
    ["pipeline"],                        # the protocol: Work, Outcome, Findings, run_stages
    ["exact"],                           # the exact kernels and the exact contact path
    ["filter", "separation", "rigid"],   # the stages: linear contact, minimum separation, rigid motion
    ["questions"],                       # the stage lists of both motion models
    ["api"],                             # the entry points, validation, the C API
    ["scene"],                           # scenes, broad phase, narrow phase over candidates
]
PUBLIC = "exactccd"

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def layer_of(folder):
    for level, folders in enumerate(LAYERS):
        if folder in folders:
            return level
    return None


def violations(lib):
    found = []
    for path in sorted(lib.rglob("*")):
        if path.suffix not in (".hpp", ".cpp", ".h"):
            continue
        folder = path.relative_to(lib).parts[0]
        own = layer_of(folder)
        where = path.relative_to(lib.parent)
        if own is None:
            found.append(f"{where}: folder '{folder}' is in no layer of tests/lint/include_order.py")
            continue
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            target = match.group(1).split("/")[0]
            if target == PUBLIC or target == folder:
                continue
            level = layer_of(target)
            if level is None:
                found.append(f"{where}:{number}: includes \"{match.group(1)}\", in no known folder")
            elif level >= own:
                relation = "a sibling" if level == own else "a higher layer"
                found.append(f"{where}:{number}: {folder}/ includes \"{match.group(1)}\" of {relation} ({target}/)")
    return found


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    lib = pathlib.Path(sys.argv[1])
    found = violations(lib)
    for v in found:
        print(v)
    if found:
        print(f"{len(found)} include(s) against the layer order (docs/architecture.md, \"Layers\")")
        return 1
    print("every include of lib/ follows the layer order")
    return 0


if __name__ == "__main__":
    sys.exit(main())
