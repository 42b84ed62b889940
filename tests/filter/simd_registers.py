#!/usr/bin/env python3
"""Each SIMD level of the block stages was compiled for its registers.

The block stages (lib/filter/volume_block.cpp, ...) compile one function per level with GCC
target attributes, named after it: baseline (SSE2), avx2, avx512. Disassembling the library,
every such function must hold packed arithmetic and packed comparisons (a block stage's loops
compute values, then decide on them; a loop the compiler did not vectorize has neither) on the
registers of its level: avx512 ones zmm registers, avx2 ones ymm registers and no zmm,
baseline ones xmm and neither of the others; and none a fused multiply-add (the block forms
must round as the per-query stages do: -ffp-contract=off).
Exits 1 listing every function that does not, or when no function of a level is found.

usage: simd_registers.py LIBRARY OBJDUMP
"""
import re
import subprocess
import sys

LEVELS = {"avx512": ("zmm", ()), "avx2": ("ymm", ("zmm",)), "baseline": ("xmm", ("ymm", "zmm"))}
HEADER = re.compile(r"^[0-9a-f]+ <(.*)>:$")
LEVEL = re.compile(r"::\(anonymous namespace\)::(avx512|avx2|baseline)\(")
ARITHMETIC = re.compile(r"\bv?(mul|add|sub)pd\b")  # the arithmetic of a loop over lanes
COMPARISON = re.compile(r"\bv?cmp[a-z]*pd\b")      # the decisions of a loop over lanes


def functions(disassembly):
    """(name, body lines) of every exactccd function named after a level."""
    name, body = None, []
    for line in disassembly.splitlines():
        header = HEADER.match(line)
        if header:
            if name:
                yield name, body
            name = header.group(1) if "exactccd::" in header.group(1) and LEVEL.search(header.group(1)) else None
            body = []
        elif name:
            body.append(line)
    if name:
        yield name, body


def problems(disassembly):
    found, seen = [], {level: 0 for level in LEVELS}
    for name, body in functions(disassembly):
        level = LEVEL.search(name).group(1)
        seen[level] += 1
        text = "\n".join(body)
        register, forbidden = LEVELS[level]
        for what, pattern in (("arithmetic", ARITHMETIC), ("comparison", COMPARISON)):
            if not any(pattern.search(l) and f"%{register}" in l for l in body):
                found.append(f"{name}: no packed {what} on {register} registers (a loop not vectorized)")
        for other in forbidden:
            if f"%{other}" in text:
                found.append(f"{name}: uses {other} registers, beyond its level")
        if "fmadd" in text or "fmsub" in text or "fnmadd" in text:
            found.append(f"{name}: a fused multiply-add (rounds differently from the per-query stage)")
    found += [f"no block-stage function compiled for {level}" for level, n in seen.items() if n == 0]
    return found, seen


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    out = subprocess.run([sys.argv[2], "-d", "-C", "--no-show-raw-insn", sys.argv[1]], capture_output=True,
                         text=True, check=True).stdout
    found, seen = problems(out)
    for p in found:
        print(p)
    print("functions per level: " + ", ".join(f"{level} {n}" for level, n in seen.items()))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
