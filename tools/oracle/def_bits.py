#!/usr/bin/env python3
"""Writes tests/oracle/corpus/dis/def-bits/*.fxo: ps_3_0 bytecode whose `def` holds one 32-bit
pattern that assembly text cannot spell (NaN payloads, signalling NaNs, negative NaNs,
denormals, -0, the extremes), for `D3DDisassemble` to list (tools/oracle/regen, `dis` mode).

Each file is `ps_3_0; def c0, BITS, 0, 0, 1.0; mov oC0, c0; end`, tokens written by hand:
version 0xFFFF0300, def 0x05000051 with destination c0 (0xA00F0000), mov 0x02000001 to oC0
(0x800F0800) from c0 (0xA0E40000), end 0x0000FFFF. Standard library only.

    tools/oracle/def_bits.py [--out DIR]
"""

import argparse
import os
import struct

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

# (file name, bits): what each pattern is
PATTERNS = [
    ("pos-inf", 0x7F800000),
    ("neg-inf", 0xFF800000),
    ("qnan", 0x7FC00000),
    ("qnan-neg", 0xFFC00000),
    ("qnan-payload-1", 0x7FC00001),
    ("qnan-payload-high", 0x7FE00000),
    ("qnan-payload-all", 0x7FFFFFFF),
    ("qnan-neg-payload-1", 0xFFC00001),
    ("qnan-neg-payload-high", 0xFFE00000),
    ("qnan-neg-payload-all", 0xFFFFFFFF),
    ("snan-1", 0x7F800001),
    ("snan-payload-all", 0x7FBFFFFF),
    ("snan-neg-1", 0xFF800001),
    ("snan-neg-payload-all", 0xFFBFFFFF),
    ("denormal-min", 0x00000001),
    ("denormal-max", 0x007FFFFF),
    ("denormal-neg-min", 0x80000001),
    ("denormal-neg-max", 0x807FFFFF),
    ("neg-zero", 0x80000000),
    ("normal-min", 0x00800000),
    ("normal-max", 0x7F7FFFFF),
    ("normal-neg-max", 0xFF7FFFFF),
]


def shader(bits):
    one = struct.unpack("<I", struct.pack("<f", 1.0))[0]
    tokens = [0xFFFF0300, 0x05000051, 0xA00F0000, bits, 0, 0, one,
              0x02000001, 0x800F0800, 0xA0E40000, 0x0000FFFF]
    return struct.pack(f"<{len(tokens)}I", *tokens)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(ROOT, "tests", "oracle", "corpus", "dis",
                                                  "def-bits"))
    out = ap.parse_args().out
    os.makedirs(out, exist_ok=True)
    for name, bits in PATTERNS:
        with open(os.path.join(out, f"{name}.fxo"), "wb") as f:
            f.write(shader(bits))


if __name__ == "__main__":
    main()
