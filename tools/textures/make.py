#!/usr/bin/env python3
"""Writes the small DDS files of assets/textures/ and tests/d3d9_conformance/textures/
byte by byte from the DDS layout (DDS_HEADER, DDS_PIXELFORMAT), independently of
ps30's reader, so that the texels the guide and the tests expect are the ones
written here.

    python3 tools/textures/make.py      # from the repository root
"""
import struct

DDSD = 0x1 | 0x2 | 0x4 | 0x1000  # CAPS | HEIGHT | WIDTH | PIXELFORMAT
MIPMAPCOUNT, DEPTH, LINEARSIZE, PITCH = 0x20000, 0x800000, 0x80000, 0x8
CAPS_TEXTURE, CAPS_COMPLEX, CAPS_MIPMAP = 0x1000, 0x8, 0x400000
CUBE_ALL = 0x200 | 0xFC00
VOLUME = 0x200000


def header(w, h, levels, pf, depth=0, caps2=0, flags=0):
    flags |= DDSD | (MIPMAPCOUNT if levels > 1 else 0) | (DEPTH if depth else 0)
    caps = CAPS_TEXTURE | ((CAPS_COMPLEX | CAPS_MIPMAP) if levels > 1 else 0)
    if caps2:
        caps |= CAPS_COMPLEX
    return (b"DDS " + struct.pack("<7I", 124, flags, h, w, 0, depth, levels)
            + bytes(44) + pf + struct.pack("<5I", caps, caps2, 0, 0, 0))


def argb_pf():
    return struct.pack("<8I", 32, 0x41, 0, 32, 0xFF0000, 0xFF00, 0xFF, 0xFF000000)


def dxt_pf(fourcc):
    return struct.pack("<2I4s5I", 32, 0x4, fourcc, 0, 0, 0, 0, 0)


def dxt1_pf():
    return dxt_pf(b"DXT1")


def argb(r, g, b, a=255):
    return bytes([b, g, r, a])


# A cube of 2×2 faces with two levels. Level 0 of face f is one colour,
# (40·(f+1), 0, 0); level 1 (1×1) is (0, 40·(f+1), 0): authored, not the
# average of level 0.
cube = b""
for f in range(6):
    cube += argb(40 * (f + 1), 0, 0) * 4 + argb(0, 40 * (f + 1), 0)
open("assets/textures/faces.dds", "wb").write(
    header(2, 2, 2, argb_pf(), caps2=CUBE_ALL, flags=PITCH) + cube)

# A 2×2×2 volume: texel (x, y, z) has red 20·(x + 2y + 4z), green 255·z.
vol = b"".join(argb(20 * (x + 2 * y + 4 * z), 255 * z, 0)
               for z in range(2) for y in range(2) for x in range(2))
open("assets/textures/lut.dds", "wb").write(
    header(2, 2, 1, argb_pf(), depth=2, caps2=VOLUME, flags=PITCH) + vol)

# One DXT1 block: colour0 0xF800 (red), colour1 0x001F (blue), row 0's
# indices 0, 1, 2, 3 (c2 = ⅔ red + ⅓ blue = (170, 0, 85), c3 = (85, 0, 170)),
# rows 1-3 index 0.
block = struct.pack("<HHI", 0xF800, 0x001F, 0xE4)
open("assets/textures/dxt1.dds", "wb").write(
    header(4, 4, 1, dxt1_pf(), flags=LINEARSIZE) + block)

# The conformance corpus's textures (tests/d3d9_conformance/README.md says what
# each case reads from them; tests/d3d9_conformance.rs computes the same texels
# from the same formulas).
CONF = "tests/d3d9_conformance/textures/"

# A cube of 4×4 faces with three authored levels (4, 2, 1): texel (x, y) of
# level l of face f is (40·(f+1), 80·l + 16·x, 60·y).
cube = b""
for f in range(6):
    for level, side in enumerate((4, 2, 1)):
        cube += b"".join(argb(40 * (f + 1), 80 * level + 16 * x, 60 * y)
                         for y in range(side) for x in range(side))
open(CONF + "cube.dds", "wb").write(
    header(4, 4, 3, argb_pf(), caps2=CUBE_ALL, flags=PITCH) + cube)

# A 4×4×4 volume with three authored levels (4, 2, 1): texel (x, y, z) of
# level l is (60·x, 60·y, 60·z) with alpha 255 − 100·l.
vol = b""
for level, side in enumerate((4, 2, 1)):
    vol += b"".join(argb(60 * x, 60 * y, 60 * z, 255 - 100 * level)
                    for z in range(side) for y in range(side) for x in range(side))
open(CONF + "volume.dds", "wb").write(
    header(4, 4, 3, argb_pf(), depth=4, caps2=VOLUME, flags=PITCH) + vol)

# A 4×4 2D texture with three authored levels, one colour each: (200, 0, 0),
# (0, 200, 0), (0, 0, 200) — a box filter of level 0 would give red again.
mips = b"".join(argb(*(200 if c == level else 0 for c in range(3))) * (side * side)
                for level, side in enumerate((4, 2, 1)))
open(CONF + "mips.dds", "wb").write(header(4, 4, 3, argb_pf(), flags=PITCH) + mips)

# DXT1, 8×4: block 0 colour0 0xF800 (red), colour1 0x07E0 (green), four
# colours; row 0 indices 0, 1, 2, 3: (255, 0, 0), (0, 255, 0), (170, 85, 0),
# (85, 170, 0). Block 1 colour0 0x001F (blue) < colour1 0xF800 (red): three
# colours and transparent black; row 0 indices 0, 1, 3, 3: blue, red, then
# (0, 0, 0, 0) twice. Rows 1-3 index 0.
dxt1 = struct.pack("<HHI", 0xF800, 0x07E0, 0xE4) + struct.pack("<HHI", 0x001F, 0xF800, 0xF4)
open(CONF + "dxt1.dds", "wb").write(header(8, 4, 1, dxt_pf(b"DXT1"), flags=LINEARSIZE) + dxt1)

# DXT3, 4×4: explicit alpha, row 0 nibbles 0, 5, 10, 15 (alpha 0, 85, 170,
# 255), other rows 15; the colour block is DXT1's block 0 (always four colours).
alpha3 = struct.pack("<H", 0xFA50) + struct.pack("<H", 0xFFFF) * 3
dxt3 = alpha3 + struct.pack("<HHI", 0xF800, 0x07E0, 0xE4)
open(CONF + "dxt3.dds", "wb").write(header(4, 4, 1, dxt_pf(b"DXT3"), flags=LINEARSIZE) + dxt3)

# DXT5, 4×4: alpha0 252 > alpha1 0 (eight alphas: 252, 0, then (6·252)/7 = 216,
# 180, 144, 108, 72, 36 — all exact); row 0 codes 0, 1, 2, 7 (alpha 252, 0,
# 216, 36), other rows code 0; the colour block is DXT1's block 0.
codes = [0, 1, 2, 7] + [0] * 12
bits = sum(c << (3 * i) for i, c in enumerate(codes))
dxt5 = bytes([252, 0]) + bits.to_bytes(6, "little") + struct.pack("<HHI", 0xF800, 0x07E0, 0xE4)
open(CONF + "dxt5.dds", "wb").write(header(4, 4, 1, dxt_pf(b"DXT5"), flags=LINEARSIZE) + dxt5)
