#!/usr/bin/env python3
"""Writes the assembly probes of the oracle corpus: tests/oracle/corpus/asm/ops/.

    tools/oracle/probes.py [--out DIR]      DIR defaults to tests/oracle/corpus/asm/ops

Each probe is a small complete ps_3_0 shader that varies one thing against a baseline
Microsoft's assembler accepts: the register file of one operand, one source or destination
modifier, the predicate, a write mask or swizzle, a def/defi/defb value, a dcl form, a
sampler type, a register index at the edge of its range, or an instruction ps_3_0 does not
have. The lines around the probed one are only what it needs (declarations of the inputs and
samplers it reads, temporaries written before they are read, a loop around aL, a setp before
p0), so a refusal is about the probed thing. Both answers are wanted: the fixtures record
which forms Microsoft accepts and which it refuses, with its message.

The folder is wholly this script's: it is emptied of .psh files and rewritten, in a fixed
order with fixed names, so two runs give the same bytes (tools/oracle/regen --check compares
them with the committed probes). Standard library only.
"""

import argparse
import os
import sys

# --- the shader around a probe ------------------------------------------------------------

# Temporaries a probe may read, each written first from c0 (defined below).
TEMPS = ["r1", "r2", "r3", "r4", "r5"]


def shader(body, needs=(), sampler="2d", decls=()):
    """A complete ps_3_0 shader: the lines `needs` asks for and `decls` (declarations, after
    the ones `needs` makes), then `body` (a list of lines).

    needs: r1..r5 (written before use), v0 v1 (texcoord inputs), vPos, vFace, s0 (a sampler
    of type `sampler`), p0 (set by setp), i0 (defined), loop (body inside loop aL, i0)."""
    needs = set(needs)
    if "loop" in needs:
        needs.add("i0")
    lines = ["ps_3_0"]
    lines.append("def c0, 1, 0.5, 0.25, 2")
    if "i0" in needs:
        lines.append("defi i0, 2, 0, 1, 0")
    for v in ("v0", "v1"):
        if v in needs:
            lines.append(f"dcl_texcoord{v[1]} {v}")
    if "vPos" in needs:
        lines.append("dcl vPos.xy")
    if "vFace" in needs:
        lines.append("dcl vFace")
    if "s0" in needs:
        lines.append(f"dcl_{sampler} s0")
    lines.extend(decls)
    if "p0" in needs:
        needs.update(("r1", "r2"))
    for r in TEMPS:
        if r in needs:
            lines.append(f"mov {r}, c0")
    if "p0" in needs:
        lines.append("setp_gt p0, r1, r2")
    if "loop" in needs:
        lines.append("loop aL, i0")
        lines.extend("    " + b for b in body)
        lines.append("endloop")
    else:
        lines.extend(body)
    return "\n".join(lines) + "\n"


# --- the instructions ----------------------------------------------------------------------


class Op:
    """One instruction's baseline: `dst` (with its mask), its sources, and how the
    probe line sits in a shader (`wrap`: the lines before and after it)."""

    def __init__(self, name, dst, srcs, needs=(), before=(), after=(), kind="arith",
                 mods=True, sampler_at=None):
        self.name = name
        self.dst = dst  # (register, mask) or None
        self.srcs = srcs  # [(text, needs, scalar)]
        self.needs = set(needs)
        self.before = list(before)
        self.after = list(after)
        self.kind = kind
        self.mods = mods  # whether destination modifiers and predication apply
        self.sampler_at = sampler_at

    def line(self, mnemonic=None, dst=None, srcs=None, pred=""):
        words = []
        d = self.dst if dst is None else dst
        if d is not None:
            words.append(d[0] + d[1])
        words.extend(s[0] for s in (self.srcs if srcs is None else srcs))
        text = (mnemonic or self.name) + (" " + ", ".join(words) if words else "")
        return (f"({pred}) " if pred else "") + text

    def needs_of(self, srcs=None):
        n = set(self.needs)
        for s in self.srcs if srcs is None else srcs:
            n |= set(s[1])
        return n

    def body(self, line):
        return self.before + [line] + self.after


def S(reg, scalar=False):
    """A baseline source: a temporary written before the probe."""
    return (reg + (".x" if scalar else ""), {reg}, scalar)


def arith(name, nsrc, dst_mask="", scalar=(), matrix=False):
    srcs = []
    for k in range(nsrc):
        reg = f"r{k + 1}"
        if matrix and k == 1:
            srcs.append(("r2", {"r2", "r3", "r4", "r5"}, False))
        else:
            srcs.append(S(reg, k in scalar))
    return Op(name, ("r0", dst_mask), srcs)


OPS = [
    Op("nop", None, []),
    arith("mov", 1),
    arith("add", 2),
    arith("sub", 2),
    arith("mad", 3),
    arith("mul", 2),
    arith("rcp", 1, scalar=(0,)),
    arith("rsq", 1, scalar=(0,)),
    arith("dp3", 2),
    arith("dp4", 2),
    arith("min", 2),
    arith("max", 2),
    arith("exp", 1, scalar=(0,)),
    arith("log", 1, scalar=(0,)),
    arith("lrp", 3),
    arith("frc", 1),
    arith("m4x4", 2, matrix=True),
    arith("m4x3", 2, ".xyz", matrix=True),
    arith("m3x4", 2, matrix=True),
    arith("m3x3", 2, ".xyz", matrix=True),
    arith("m3x2", 2, ".xy", matrix=True),
    arith("pow", 2, scalar=(0, 1)),
    arith("crs", 2, ".xyz"),
    arith("abs", 1),
    arith("nrm", 1, ".xyz"),
    arith("sincos", 1, ".xy", scalar=(0,)),
    arith("cmp", 3),
    arith("dp2add", 3, scalar=(2,)),
    arith("dsx", 1),
    arith("dsy", 1),
    Op("texkill", None, [S("r1")], kind="tex"),
    Op("texld", ("r0", ""), [S("r1"), ("s0", {"s0"}, False)], kind="tex", sampler_at=1),
    Op("texldp", ("r0", ""), [S("r1"), ("s0", {"s0"}, False)], kind="tex", sampler_at=1),
    Op("texldb", ("r0", ""), [S("r1"), ("s0", {"s0"}, False)], kind="tex", sampler_at=1),
    Op("texldl", ("r0", ""), [S("r1"), ("s0", {"s0"}, False)], kind="tex", sampler_at=1),
    Op("texldd", ("r0", ""), [S("r1"), ("s0", {"s0"}, False), S("r2"), S("r3")], kind="tex",
       sampler_at=1),
    Op("setp_gt", ("p0", ""), [S("r1"), S("r2")], kind="setp"),
    Op("if_gt", None, [S("r1", True), S("r2", True)], before=[], after=["mov r0, c0", "endif"],
       kind="flow", mods=False),
    Op("if", None, [("b0", set(), False)], after=["mov r0, c0", "endif"], kind="flow",
       mods=False),
    Op("break_gt", None, [S("r1", True), S("r2", True)], needs={"i0"}, before=["rep i0"],
       after=["endrep"], kind="flow", mods=False),
    Op("breakp", None, [("p0.x", {"p0"}, False)], needs={"i0"}, before=["rep i0"],
       after=["endrep"], kind="flow", mods=False),
    Op("rep", None, [("i0", {"i0"}, False)], after=["mov r0, c0", "endrep"], kind="flow",
       mods=False),
    Op("loop", None, [("aL", set(), False), ("i0", {"i0"}, False)],
       after=["mov r0, c0", "endloop"], kind="flow", mods=False),
    Op("callnz", None, [("l1", set(), False), ("b0", set(), False)],
       after=["ret", "label l1", "mov r0, c0", "ret"], kind="flow", mods=False),
    Op("call", None, [("l1", set(), False)], after=["ret", "label l1", "mov r0, c0", "ret"],
       kind="flow", mods=False),
]

# Register files as a source operand: (name in the probe's file name, text, needs).
SOURCE_FILES = [
    ("v", "v0", {"v0"}),
    ("c", "c1", set()),
    ("i", "i0", {"i0"}),
    ("b", "b0", set()),
    ("s", "s0", {"s0"}),
    ("p0", "p0", {"p0"}),
    ("aL", "aL", {"loop"}),
    ("oC0", "oC0", set()),
    ("oDepth", "oDepth", set()),
    ("vPos", "vPos", {"vPos"}),
    ("vFace", "vFace", {"vFace"}),
    ("v-aL", "v[aL]", {"loop", "v0"}),
]

# Register files as the destination: (name, register, needs).
DEST_FILES = [
    ("oC0", "oC0", set()),
    ("oC4", "oC4", set()),
    ("oDepth", "oDepth", set()),
    ("v", "v0", {"v0"}),
    ("c", "c1", set()),
    ("b", "b0", set()),
    ("s", "s0", {"s0"}),
    ("p0", "p0", set()),
    ("aL", "aL", {"loop"}),
    ("vFace", "vFace", {"vFace"}),
]

# Source modifiers: (name, how a register is written with it).
SOURCE_MODIFIERS = [
    ("neg", "-{}"),
    ("abs", "{}_abs"),
    ("neg-abs", "-{}_abs"),
    ("bias", "{}_bias"),
    ("bx2", "{}_bx2"),
    ("x2", "{}_x2"),
    ("dz", "{}_dz"),
    ("dw", "{}_dw"),
    ("comp", "1-{}"),
    ("not", "!{}"),
]

# Destination modifiers, each a suffix of the mnemonic.
DEST_MODIFIERS = ["_sat", "_pp", "_centroid", "_sat_pp", "_pp_sat", "_centroid_pp", "_x2"]

PREDICATES = ["p0", "!p0", "p0.x", "!p0.w", "p0.xy"]


def with_swizzle(text, swizzle):
    """A source's text with its register's swizzle replaced."""
    base = text.split(".")[0]
    return base + swizzle


def op_probes(op):
    """The probes of one instruction: baseline, each source position × register file,
    each destination register file, source and destination modifiers, predication."""
    out = []

    def add(name, body, needs, sampler="2d"):
        out.append((f"{op.name}/{name}.psh", shader(body, needs, sampler)))

    add("base", op.body(op.line()), op.needs_of())
    for k, src in enumerate(op.srcs):
        if src[0].startswith("l"):
            continue  # a label, not a register
        scalar = src[2]
        for fname, text, needs in SOURCE_FILES:
            t = text + (".x" if scalar else "")
            srcs = list(op.srcs)
            srcs[k] = (t, needs, scalar)
            add(f"src{k}-{fname}", op.body(op.line(srcs=srcs)), op.needs_of(srcs))
    if op.dst is not None and op.kind != "setp":
        for fname, reg, needs in DEST_FILES:
            dst = (reg, op.dst[1])
            add(f"dst-{fname}", op.body(op.line(dst=dst)), op.needs_of() | needs)
    # Source modifiers on every temporary source: the first keeps the name
    # `srcmod-M`, the others are `srcKmod-M` (`sub` turns its second source's
    # negation around, so each position matters).
    for k, src in enumerate(op.srcs):
        if not src[0].startswith("r"):
            continue
        for mname, form in SOURCE_MODIFIERS:
            srcs = list(op.srcs)
            srcs[k] = (form.format(srcs[k][0]),) + srcs[k][1:]
            prefix = "srcmod" if k == 0 else f"src{k}mod"
            add(f"{prefix}-{mname}", op.body(op.line(srcs=srcs)), op.needs_of())
    if op.mods:
        for m in DEST_MODIFIERS:
            add(f"dstmod{m.replace('_', '-')}", op.body(op.line(mnemonic=op.name + m)),
                op.needs_of())
        for p in PREDICATES:
            name = "pred-" + p.replace("!", "not-").replace(".", "-")
            add(name, op.body(op.line(pred=p)), op.needs_of() | {"p0"})
    return out


# --- topics --------------------------------------------------------------------------------

XYZW = "xyzw"


def swizzles():
    """mov from a temporary through every swizzle of 1 to 4 letters, and rgba spellings."""
    out = []
    names = [""]
    for n in range(1, 5):
        names = [a + b for a in names for b in XYZW] if n > 1 else list(XYZW)
        for s in names:
            body = [f"mov r0, r1.{s}"]
            out.append((f"swizzle/{n}/{s}.psh", shader(body, {"r1"})))
    for s in ["rgba", "bgra", "a", "gr", "rrra", "xyba"]:
        out.append((f"swizzle/rgba/{s}.psh", shader([f"mov r0, r1.{s}"], {"r1"})))
    # the swizzle of a scalar source
    for op, line in [("rcp", "rcp r0, r1{}"), ("pow-a", "pow r0, r1{}, r2.x"),
                     ("pow-b", "pow r0, r1.x, r2{}"), ("dp2add", "dp2add r0, r1, r2, r3{}"),
                     ("sincos", "sincos r0.xy, r1{}"), ("if_gt", "if_gt r1{}, r2.x")]:
        for s in ["", ".x", ".y", ".w", ".xy", ".xxxx", ".yyyy", ".xyzw", ".wzyx"]:
            body = [line.format(s)] + (["mov r0, c0", "endif"] if op == "if_gt" else [])
            out.append((f"swizzle/scalar/{op}{s.replace('.', '-') or '-none'}.psh",
                        shader(body, {"r1", "r2", "r3"})))
    return out


def masks():
    """Every write mask (ordered, then some out of order and rgba spellings) on mov, and
    every ordered mask on instructions that restrict theirs."""
    ordered = []
    for bits in range(1, 16):
        ordered.append("".join(XYZW[i] for i in range(4) if bits >> i & 1))
    out = []
    for m in ordered + ["yx", "zyx", "wx", "xx", "rgb", "a", "rg", "rgba"]:
        out.append((f"mask/mov/{m}.psh", shader([f"mov r0.{m}, r1"], {"r1"})))
    lines = {
        "sincos": ("sincos r0.{}, r1.x", {"r1"}, "2d"),
        "nrm": ("nrm r0.{}, r1", {"r1"}, "2d"),
        "crs": ("crs r0.{}, r1, r2", {"r1", "r2"}, "2d"),
        "m3x2": ("m3x2 r0.{}, r1, r2", {"r1", "r2", "r3"}, "2d"),
        "m4x3": ("m4x3 r0.{}, r1, r2", {"r1", "r2", "r3", "r4"}, "2d"),
        "texld": ("texld r0.{}, r1, s0", {"r1", "s0"}, "2d"),
        "setp": ("setp_gt p0.{}, r1, r2", {"r1", "r2"}, "2d"),
        "oC0": ("mov oC0.{}, r1", {"r1"}, "2d"),
        "oDepth": ("mov oDepth.{}, r1.x", {"r1"}, "2d"),
    }
    for op, (line, needs, sampler) in lines.items():
        for m in ordered:
            out.append((f"mask/{op}/{m}.psh", shader([line.format(m)], needs, sampler)))
    return out


SAMPLER_TYPES = ["2d", "cube", "volume"]


def samplers():
    """The texld family on each sampler type, with the forms texture instructions take."""
    out = []
    forms = [
        ("base", "{op} r0, r1, s0", {"r1"}),
        ("coord-v", "{op} r0, v0, s0", {"v0"}),
        ("coord-swz", "{op} r0, r1.yzxw, s0", {"r1"}),
        ("coord-c", "{op} r0, c1, s0", set()),
        ("mask-xy", "{op} r0.xy, r1, s0", {"r1"}),
        ("sampler-swz", "{op} r0, r1, s0.yzwx", {"r1"}),
        ("pp", "{op}_pp r0, r1, s0", {"r1"}),
        ("centroid", "{op}_centroid r0, r1, s0", {"r1"}),
        ("s15", "{op} r0, r1, s15", {"r1"}),
    ]
    for op in ["texld", "texldp", "texldb", "texldl", "texldd"]:
        for st in SAMPLER_TYPES:
            for fname, line, needs in forms:
                text = line.format(op=op)
                if op == "texldd":
                    text += ", r2, r3"
                    needs = needs | {"r2", "r3"}
                decls = [f"dcl_{st} s15"] if fname == "s15" else []
                n = set(needs) if fname == "s15" else needs | {"s0"}
                out.append((f"sampler/{op}/{st}-{fname}.psh", shader([text], n, st, decls)))
    for st in SAMPLER_TYPES + ["1d", "3d", "2D", "CUBE"]:
        name = st if st.islower() or st.isdigit() else st.lower() + "-upper"
        out.append((f"sampler/dcl/{name}.psh",
                    shader(["texld r0, r1, s0"], {"r1"}, decls=[f"dcl_{st} s0"])))
    for fname, decl in [("undeclared", None), ("dcl-plain", "dcl s0"),
                        ("dcl-mask", "dcl_2d s0.xy"), ("dcl-pp", "dcl_2d_pp s0"),
                        ("twice", "dcl_2d s0\ndcl_cube s0"), ("s16", "dcl_2d s16")]:
        decls = decl.split("\n") if decl else []
        out.append((f"sampler/dcl/{fname}.psh", shader(["texld r0, r1, s0"], {"r1"}, decls=decls)))
    return out


DEF_VALUES = [
    "0", "1", "-1", "0.5", "-0.5", ".5", "-.5", "5.", "1.0", "-0", "-0.0", "+1", "+0.5",
    "0.95", "0.949999988", "0.1", "0.3333333", "3.14159265", "1e3", "1E3", "1e-3", "1.5e+2",
    "-2.5e-4", "1e38", "3.40282347e38", "3.4028236e38", "1e39", "-1e39", "1.17549435e-38",
    "1e-40", "1.4e-45", "1e-46", "123456789", "16777217", "0.000001", "65504", "65505",
    "1.#INF", "inf", "nan", "0x3f800000", "1f", "1.5h", "2,", "1 .5", "--1", "1e", "e3",
]


def defs():
    """def, defi and defb: value formats and registers."""
    out = []
    for k, v in enumerate(DEF_VALUES):
        out.append((f"def/value/{k:02}.psh",
                    f"ps_3_0\ndef c1, {v}, 0, 0, 1\nmov r0, c1\n"))
    for name, line in [
        ("c0", "def c0, 1, 2, 3, 4"), ("c223", "def c223, 1, 2, 3, 4"),
        ("c224", "def c224, 1, 2, 3, 4"), ("c255", "def c255, 1, 2, 3, 4"),
        ("r0", "def r0, 1, 2, 3, 4"), ("i0", "def i0, 1, 2, 3, 4"), ("v0", "def v0, 1, 2, 3, 4"),
        ("mask", "def c1.x, 1, 2, 3, 4"), ("three", "def c1, 1, 2, 3"),
        ("five", "def c1, 1, 2, 3, 4, 5"), ("one", "def c1, 1"), ("twice", "def c1, 1, 2, 3, 4\ndef c1, 5, 6, 7, 8"),
        ("pp", "def_pp c1, 1, 2, 3, 4"), ("sat", "def_sat c1, 1, 2, 3, 4"),
        ("after-code", "mov r0, c0\ndef c1, 1, 2, 3, 4"),
    ]:
        out.append((f"def/form/{name}.psh", f"ps_3_0\n{line}\nmov r0, c1\n"))
    for k, v in enumerate(["0", "1", "-1", "255", "256", "-128", "-129", "2147483647",
                           "-2147483648", "4294967295", "4294967296", "1.5", "1e2", "0x10",
                           "+3", "-0", "007"]):
        for at, line in [("x", "defi i0, {}, 0, 1, 0"), ("z", "defi i0, 1, 0, {}, 0")]:
            text = f"ps_3_0\n{line.format(v)}\nmov r0, c0\nrep i0\nadd r0, r0, c0\nendrep\n"
            out.append((f"defi/value-{at}/{k:02}.psh", text))
    for name, line in [("i15", "defi i15, 1, 0, 1, 0"), ("i16", "defi i16, 1, 0, 1, 0"),
                       ("c0", "defi c0, 1, 0, 1, 0"), ("b0", "defi b0, 1, 0, 1, 0"),
                       ("three", "defi i0, 1, 0, 1"), ("float-reg", "def i0, 1, 0, 1, 0")]:
        out.append((f"defi/form/{name}.psh", f"ps_3_0\n{line}\n"))
    for k, v in enumerate(["true", "false", "TRUE", "False", "1", "0", "yes"]):
        out.append((f"defb/value/{k:02}.psh",
                    f"ps_3_0\ndefb b0, {v}\nif b0\nmov r0, c0\nendif\n"))
    for name, line in [("b15", "defb b15, true"), ("b16", "defb b16, true"),
                       ("i0", "defb i0, true"), ("c0", "defb c0, true"),
                       ("two", "defb b0, true, false")]:
        out.append((f"defb/form/{name}.psh", f"ps_3_0\n{line}\n"))
    return out


USAGES = ["position", "blendweight", "blendindices", "normal", "psize", "texcoord", "tangent",
          "binormal", "tessfactor", "positiont", "color", "fog", "depth", "sample"]


def dcls():
    """Input declarations: every usage and index, masks, modifiers, registers."""
    out = []
    for u in USAGES:
        for idx in ["", "0", "15", "16"]:
            out.append((f"dcl/usage/{u}{idx or '-none'}.psh",
                        f"ps_3_0\ndcl_{u}{idx} v0\nmov r0, v0\n"))
    ordered = ["".join(XYZW[i] for i in range(4) if b >> i & 1) for b in range(1, 16)]
    for u in ["texcoord0", "color0"]:
        for m in ordered + ["yx", "rgb"]:
            out.append((f"dcl/mask/{u}-{m}.psh", f"ps_3_0\ndcl_{u} v0.{m}\nmov r0, c0\n"))
        for mod in ["_centroid", "_pp", "_centroid_pp", "_pp_centroid", "_sat", "_x2"]:
            out.append((f"dcl/modifier/{u}{mod.replace('_', '-')}.psh",
                        f"ps_3_0\ndcl_{u}{mod} v0\nmov r0, v0\n"))
    for name, decl in [
        ("v9", "dcl_texcoord9 v9"), ("v10", "dcl_texcoord0 v10"), ("vPos-xy", "dcl vPos.xy"),
        ("vPos", "dcl vPos"), ("vPos-x", "dcl vPos.x"), ("vPos-usage", "dcl_position0 vPos"),
        ("vPos-centroid", "dcl_centroid vPos.xy"), ("vFace", "dcl vFace"),
        ("vFace-x", "dcl vFace.x"), ("oC0", "dcl_color0 oC0"), ("oDepth", "dcl_depth oDepth"),
        ("r0", "dcl_texcoord0 r0"), ("c0", "dcl_texcoord0 c0"), ("plain-v0", "dcl v0"),
        ("two-usages", "dcl_texcoord0 v0\ndcl_color0 v1"),
        ("split-mask", "dcl_texcoord0 v0.xy\ndcl_texcoord1 v0.zw"),
        ("same-usage", "dcl_texcoord0 v0\ndcl_texcoord0 v1"),
    ]:
        out.append((f"dcl/register/{name}.psh", f"ps_3_0\n{decl}\nmov r0, c0\n"))
    return out


PS1X = [
    ("tex", "tex t0"), ("texcoord", "texcoord t0"), ("texcrd", "texcrd r0, t0"),
    ("texbem", "texbem t1, t0"), ("texbeml", "texbeml t1, t0"),
    ("texreg2ar", "texreg2ar t1, t0"), ("texreg2gb", "texreg2gb t1, t0"),
    ("texreg2rgb", "texreg2rgb t1, t0"), ("texm3x2pad", "texm3x2pad t1, t0"),
    ("texm3x2tex", "texm3x2tex t1, t0"), ("texm3x3pad", "texm3x3pad t1, t0"),
    ("texm3x3tex", "texm3x3tex t1, t0"), ("texm3x3spec", "texm3x3spec t1, t0, c0"),
    ("texm3x3vspec", "texm3x3vspec t1, t0"), ("texdp3", "texdp3 t1, t0"),
    ("texdp3tex", "texdp3tex t1, t0"), ("texm3x2depth", "texm3x2depth t1, t0"),
    ("texdepth", "texdepth r5"), ("bem", "bem r0.xy, r1, r2"), ("cnd", "cnd r0, r1, r2, r3"),
    ("phase", "phase"), ("sge", "sge r0, r1, r2"), ("slt", "slt r0, r1, r2"),
    ("dst", "dst r0, r1, r2"), ("lit", "lit r0, r1"), ("mova", "mova a0.x, r1.x"),
    ("expp", "expp r0, r1.x"), ("logp", "logp r0, r1.x"), ("sgn", "sgn r0, r1, r2, r3"),
    ("texm3x3", "texm3x3 t1, t0"), ("setp-nocomp", "setp p0, r1, r2"),
    ("if-bad-comp", "if_xx r1.x, r2.x\nendif"), ("break-bad-comp", "rep i0\nbreak_xx r1.x, r2.x\nendrep"),
]


def ps1x():
    """Instructions of other shader models (ps_1_x, vertex shaders) and bad comparisons."""
    return [(f"other/{name}.psh", shader(line.split("\n"), {"r1", "r2", "r3", "i0"}))
            for name, line in PS1X]


def registers():
    """Register indices at the edges of their ranges, and the relative addressing forms."""
    out = []
    for name, line, needs in [
        ("r31", "mov r31, c0", set()), ("r32", "mov r32, c0", set()),
        ("c223", "mov r0, c223", set()), ("c224", "mov r0, c224", set()),
        ("c255", "mov r0, c255", set()), ("c256", "mov r0, c256", set()),
        ("i15", "rep i15\nendrep", set()), ("i16", "rep i16\nendrep", set()),
        ("b15", "if b15\nendif", set()), ("b16", "if b16\nendif", set()),
        ("v9", "dcl_texcoord9 v9\nmov r0, v9", set()),
        ("oC1", "mov oC1, c0", set()), ("oC3", "mov oC3, c0", set()),
        ("p1", "setp_gt p1, r1, r2", {"r1", "r2"}),
        ("p0-read", "mov r0, p0", {"p0"}),
        ("t0", "mov r0, t0", set()), ("a0", "mov r0, a0", set()),
        ("o-plain", "mov o0, c0", set()), ("oPos", "mov oPos, c0", set()),
        ("oT0", "mov oT0, c0", set()), ("x0", "mov r0, x0", set()),
        ("upper-R", "mov R0, C0", set()), ("space-index", "mov r0, c 1", set()),
    ]:
        out.append((f"regs/index/{name}.psh", shader(line.split("\n"), needs)))
    for name, src, needs in [
        ("c-aL", "c[aL]", set()), ("c-aL-1", "c[aL+1]", set()), ("c-aL-sp", "c[aL + 1]", set()),
        ("c1-aL", "c1[aL]", set()), ("c-aL-223", "c[aL+223]", set()),
        ("c-aL-224", "c[aL+224]", set()), ("c-aL-minus", "c[aL-1]", set()),
        ("c1-aL-2", "c1[aL+2]", set()),
        ("c-aL-x", "c[aL.x]", set()), ("c-a0", "c[a0.x]", set()),
        ("c-aL-swz", "c[aL+1].yzwx", set()), ("c-aL-neg", "-c[aL+1]", set()),
        ("c-aL-abs", "c[aL+1]_abs", set()),
        ("v-aL", "v[aL]", {"v0"}), ("v0-aL", "v0[aL]", {"v0"}), ("v-aL-1", "v[aL+1]", {"v0", "v1"}),
        ("v1-aL", "v1[aL]", {"v0", "v1"}),
        ("r-aL", "r[aL]", {"r1"}), ("i-aL", "i[aL]", set()), ("b-aL", "b[aL]", set()),
        ("s-aL", "s[aL]", {"s0"}), ("oC-aL", "oC[aL]", set()),
    ]:
        out.append((f"regs/relative/{name}.psh",
                    shader([f"mov r0, {src}"], needs | {"loop"})))
    for name, dst in [("oC-aL", "oC[aL]"), ("r-aL", "r[aL]"), ("oC0-aL", "oC0[aL]")]:
        out.append((f"regs/relative/dst-{name}.psh", shader([f"mov {dst}, c0"], {"loop"})))
    return out


# --- the whole corpus ----------------------------------------------------------------------


def probes():
    """Every probe as (path below ops/, text), in a fixed order."""
    out = []
    for op in OPS:
        out.extend(op_probes(op))
    for topic in (swizzles, masks, samplers, defs, dcls, ps1x, registers):
        out.extend(topic())
    # Wine's file names are case-insensitive: names must differ in more than case
    paths = [p.lower() for p, _ in out]
    dupes = sorted({p for p in paths if paths.count(p) > 1})
    if dupes:
        raise SystemExit(f"probes.py: duplicate probe names: {dupes[:5]}")
    return out


README = """# Assembly probes (generated)

Every `.psh` below this folder is written by `tools/oracle/probes.py`; do not edit them by
hand: change the script and run `tools/oracle/regen`. Each probe is a small complete ps_3_0
shader that varies one thing against a baseline `D3DAssemble` accepts; the lines around the
probed one only declare, define or write what it reads. docs/oracle.md describes the corpus.

| folder | what varies |
|---|---|
| `<instruction>/` | `base`: the baseline; `srcK-F`: source K from register file F; `dst-F`: the destination's file; `srcmod-M`: source modifier M on the first source, `srcKmod-M` on source K; `dstmod-M`: instruction modifier M; `pred-P`: predicate P |
| `swizzle/` | every source swizzle of 1 to 4 letters on `mov`, rgba spellings, the swizzles of scalar sources |
| `mask/` | every write mask on `mov` and on the instructions that restrict theirs |
| `sampler/` | the texld family on 2D, cube and volume samplers, and sampler declarations |
| `def/`, `defi/`, `defb/` | constant value formats and registers |
| `dcl/` | input declarations: usages and indices, masks, `_centroid`/`_pp`, registers |
| `other/` | instructions of other shader models and unknown comparisons |
| `regs/` | register indices at the edges of their ranges, relative addressing |
"""


def main():
    root = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default=os.path.join(root, "tests/oracle/corpus/asm/ops"))
    args = ap.parse_args()
    all_probes = probes()
    for dirpath, _dirs, files in os.walk(args.out):
        for f in files:
            if f.endswith(".psh"):
                os.remove(os.path.join(dirpath, f))
    for rel, text in all_probes:
        path = os.path.join(args.out, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="ascii", newline="\n") as f:
            f.write(text)
    with open(os.path.join(args.out, "README.md"), "w", encoding="ascii", newline="\n") as f:
        f.write(README)
    for dirpath, _dirs, _files in os.walk(args.out, topdown=False):
        if not os.listdir(dirpath):
            os.rmdir(dirpath)
    print(f"probes.py: {len(all_probes)} probes in {args.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
