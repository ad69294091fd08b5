#!/usr/bin/python3
"""Checks that the pack helpers of the SIMD kernels are inlined in an optimised build.

usage: inlined_pack_helpers.py LIBRARY   (the static library libfpmshell_core.a)

A pack-valued helper left out of line (a select, an FMA, a reciprocal of core/simd.hpp, or one
of libstdc++'s <experimental/simd> internals) costs a call inside the return mapping's
iterations, and every call spills the caller's vector registers: the Johnson-Cook crash kernels
ran 1.6-1.8 times slower with libstdc++'s generic stdx::fma and the pack select out of line
(docs/performance.md, "Crash kernels").
GCC's inliner decides by the size of the caller, so any change to a kernel can bring this back
without a wrong result; this check fails when the library defines such a function.
Prints each offending symbol and exits 1; exits 0 when there is none."""
import re
import subprocess
import sys

# Defined code symbols (demangled) that must not exist: helpers on packs of doubles.
FORBIDDEN = [
    # libstdc++'s SIMD implementation functions (_SimdImplBuiltin<...>::_S_fma and the like)
    re.compile(r"_SimdImpl\w*<.*>::_S_\w+"),
    # the helpers of core/simd.hpp on packs
    re.compile(r"^(\S+ )?fpmshell::(select|max|min|sqrt|any_lane|all_lanes|pipelined_reciprocal|"
               r"pipelined_sqrt|simd_detail::\w+)(<.*>)?\(.*simd"),
]


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    out = subprocess.run(["nm", "-C", "--defined-only", sys.argv[1]], capture_output=True,
                         text=True, check=True).stdout
    bad = set()
    for line in out.splitlines():
        parts = line.split(" ", 2)
        if len(parts) != 3 or parts[1] not in ("T", "t", "W", "w"):
            continue
        name = parts[2]
        if any(p.search(name) for p in FORBIDDEN):
            bad.add(name)
    for name in sorted(bad):
        print("out of line:", name[:300])
    if bad:
        print("%d pack helper(s) are functions of their own in %s: force them inline "
              "(FPMSHELL_INLINE, core/simd.hpp)" % (len(bad), sys.argv[1]))
        return 1
    print("every pack helper inlined in", sys.argv[1])
    return 0


if __name__ == "__main__":
    sys.exit(main())
