#!/usr/bin/env python3
"""Writes the small DDS files of assets/textures/ byte by byte from the DDS
layout (DDS_HEADER, DDS_PIXELFORMAT), independently of ps30's reader, so that
the texels the guide and the tests expect are the ones written here.

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


def dxt1_pf():
    return struct.pack("<2I4s5I", 32, 0x4, b"DXT1", 0, 0, 0, 0, 0)


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
