#!/usr/bin/env python3
"""Writes the per-profile probes of the oracle corpus: tests/oracle/corpus/asm/profiles/.

    tools/oracle/profile_probes.py [--out DIR]   DIR defaults to tests/oracle/corpus/asm/profiles

One folder per profile D3DAssemble reads as a version line (ps_2_0, ps_2_x, ps_3_0, vs_2_0,
vs_2_x, vs_3_0), ps_1_1-ps_1_4 (tools/oracle/ps1_probes.py: another instruction set, its own
probes), and a baseline for vs_1_1 and the HLSL-only names ps_2_a, ps_2_b, vs_2_a. In each:

* `base.psh`: the smallest shader of the profile (its version line, one output written);
* `op-NAME.psh`: the baseline plus one instruction of the whole Direct3D 9 set (pixel and
  vertex), with only the lines it needs around it (a label after the main body for `call`, a
  `rep` around `break`, a `setp` before `p0` is read). Microsoft's answer says whether the
  instruction exists in the profile, and the listing's slot line what it costs there (the
  baseline's own slots subtracted);
* `reg-FILE-N.psh`: one register read or written at the edge of its file's range (the last
  index a profile may have and the one past it);
* `limit-*.psh`: straight-line code at and past a profile's documented slot limits.

The folder is wholly this script's: it is emptied of .psh files and rewritten in a fixed order
with fixed names, so two runs give the same bytes (tools/oracle/regen --check compares them).
Standard library only.
"""

import argparse
import os
import sys

import ps1_probes

PIXEL = ["ps_2_0", "ps_2_x", "ps_3_0"]
VERTEX = ["vs_2_0", "vs_2_x", "vs_3_0"]
# A baseline each, to record what the assembler says of them: the vs_1_1 one it reads; ps_2_a, ps_2_b and vs_2_a are names of HLSL targets only (their bytecode says ps_2_x
# or vs_2_x), and as a version line D3DAssemble refuses them (X2001).
OLD = ["ps_2_a", "ps_2_b", "vs_1_1", "vs_2_a"]


def pixel(profile, body, pre=(), post=()):
    """A complete pixel shader of `profile`: constants, inputs (t0 or v0), a sampler, `pre`
    (declarations), `body`, the colour output, then `post` (subroutines)."""
    lines = [profile, "def c0, 1, 0.5, 0.25, 2"]
    lines += ["dcl_texcoord0 v0"] if profile == "ps_3_0" else ["dcl t0"]
    lines += ["dcl_2d s0"]
    lines += list(pre) + ["mov r0, c0", "mov r1, c0", "mov r2, c0"] + list(body)
    lines += ["mov oC0, r0"] + list(post)
    return "\n".join(lines) + "\n"


def vertex(profile, body, pre=(), post=()):
    """A complete vertex shader of `profile` (position in, position out)."""
    lines = [profile, "def c0, 1, 0.5, 0.25, 2", "dcl_position v0"]
    if profile == "vs_3_0":
        lines.append("dcl_position o0")
    if any(", s0" in line for line in body):
        lines.append("dcl_2d s0")
    lines += list(pre) + ["mov r0, c0", "mov r1, c0", "mov r2, c0"] + list(body)
    lines += ["mov o0, r0" if profile == "vs_3_0" else "mov oPos, r0"] + list(post)
    return "\n".join(lines) + "\n"


def texcoord(profile):
    return "v0" if profile.startswith("ps_3") else ("t0" if profile.startswith("ps") else "v0")


def ops(profile):
    """(name, body, pre, post) of one probe per instruction."""
    t = texcoord(profile)
    sub = ["ret", "label l0", "ret"]
    # ps_2_x/vs_2_x refuse a defi whose y, z, w are not 0 (X5993): rep reads only .x
    i0 = ["defi i0, 2, 0, 0, 0"]
    b0 = ["defb b0, true"]
    setp = ["setp_gt p0, r1, r2"]
    return [
        ("nop", ["nop"], [], []),
        ("mov", ["mov r0, r1"], [], []),
        ("add", ["add r0, r1, r2"], [], []),
        ("sub", ["sub r0, r1, r2"], [], []),
        ("mad", ["mad r0, r1, r2, c0"], [], []),
        ("mul", ["mul r0, r1, r2"], [], []),
        ("rcp", ["rcp r0, r1.x"], [], []),
        ("rsq", ["rsq r0, r1.x"], [], []),
        ("dp3", ["dp3 r0, r1, r2"], [], []),
        ("dp4", ["dp4 r0, r1, r2"], [], []),
        ("min", ["min r0, r1, r2"], [], []),
        ("max", ["max r0, r1, r2"], [], []),
        ("slt", ["slt r0, r1, r2"], [], []),
        ("sge", ["sge r0, r1, r2"], [], []),
        ("exp", ["exp r0, r1.x"], [], []),
        ("log", ["log r0, r1.x"], [], []),
        ("expp", ["expp r0, r1.x"], [], []),
        ("logp", ["logp r0, r1.x"], [], []),
        ("lit", ["lit r0, r1"], [], []),
        ("dst", ["dst r0, r1, r2"], [], []),
        ("lrp", ["lrp r0, r1, r2, c0"], [], []),
        ("frc", ["frc r0, r1"], [], []),
        ("m4x4", ["m4x4 r0, r1, c0"], [], []),
        ("m4x3", ["m4x3 r0.xyz, r1, c0"], [], []),
        ("m3x4", ["m3x4 r0, r1, c0"], [], []),
        ("m3x3", ["m3x3 r0.xyz, r1, c0"], [], []),
        ("m3x2", ["m3x2 r0.xy, r1, c0"], [], []),
        ("pow", ["pow r0, r1.x, r2.y"], [], []),
        ("crs", ["crs r0.xyz, r1, r2"], [], []),
        ("abs", ["abs r0, r1"], [], []),
        ("nrm", ["nrm r0, r1"], [], []),
        ("sgn", ["sgn r0, r1, r2, c0"], [], []),
        ("sincos", ["sincos r3.xy, r1.x"], [], []),
        ("sincos-2x", ["sincos r3.xy, r1.x, c1, c2"], [], []),
        ("cmp", ["cmp r0, r1, r2, c0"], [], []),
        ("dp2add", ["dp2add r0, r1, r2, c0.x"], [], []),
        ("mova", ["mova a0.x, r1.x"], [], []),
        ("dsx", ["dsx r0, r1"], [], []),
        ("dsy", ["dsy r0, r1"], [], []),
        ("texkill", [f"texkill {t}"], [], []),
        ("texld", [f"texld r0, {t}, s0"], [], []),
        ("texld-temp", ["texld r0, r1, s0"], [], []),
        ("texldp", [f"texldp r0, {t}, s0"], [], []),
        ("texldb", [f"texldb r0, {t}, s0"], [], []),
        ("texldl", [f"texldl r0, {t}, s0"], [], []),
        ("texldd", [f"texldd r0, {t}, s0, r1, r2"], [], []),
        ("setp", setp, [], []),
        ("pred", setp + ["(p0) mov r0, r1"], [], []),
        ("call", ["call l0"], [], sub),
        ("callnz", ["callnz l0, b0"], b0, sub),
        ("callnz-p", setp + ["callnz l0, p0.x"], [], sub),
        ("loop", ["loop aL, i0", "add r0, r0, r1", "endloop"], i0, []),
        ("rep", ["rep i0", "add r0, r0, r1", "endrep"], i0, []),
        ("if", ["if b0", "mov r0, r1", "endif"], b0, []),
        ("if-else", ["if b0", "mov r0, r1", "else", "mov r0, r2", "endif"], b0, []),
        ("ifc", ["if_gt r1.x, r2.x", "mov r0, r1", "endif"], [], []),
        ("if-p", setp + ["if p0.x", "mov r0, r1", "endif"], [], []),
        ("break", ["rep i0", "break", "endrep"], i0, []),
        ("breakc", ["rep i0", "break_gt r1.x, r2.x", "endrep"], i0, []),
        ("breakp", setp + ["rep i0", "breakp p0.x", "endrep"], i0, []),
        ("defi", [], i0, []),
        ("defb", [], b0, []),
    ]


# (file, last index the profile documents, register written or read as `{}`): a probe at N
# and one at N+1.
PIXEL_REGS = {
    "r": "mov r{}, c0",
    "c": "mov r0, c{}",
    "t": "texld r0, t{}, s0",
    "v": "mov r0, v{}",
    "s": "texld r0, t0, s{}",
    "oC": "mov oC{}, c0",
}
PIXEL_EDGES = {
    "ps_2_0": {"r": 11, "c": 31, "t": 7, "v": 1, "s": 15, "oC": 3},
    "ps_2_x": {"r": 31, "c": 31, "t": 7, "v": 1, "s": 15, "oC": 3},
}
VERTEX_REGS = {"r": "mov r{}, c0", "c": "mov r0, c{}", "v": "mov r0, v{}"}
VERTEX_EDGES = {
    "vs_2_0": {"r": 11, "c": 255, "v": 15},
    "vs_2_x": {"r": 31, "c": 255, "v": 15},
    "vs_3_0": {"r": 31, "c": 255, "v": 15},
}


def reg_probes(profile):
    out = []
    if profile in PIXEL_EDGES:
        for f, last in PIXEL_EDGES[profile].items():
            for n in (last, last + 1):
                line = PIXEL_REGS[f].format(n)
                pre = []
                if f == "t":
                    pre = [f"dcl t{n}"]
                elif f == "v":
                    pre = [f"dcl v{n}"]
                elif f == "s":
                    pre = [f"dcl_2d s{n}"]
                out.append((f"reg-{f}{n}", pixel(profile, [line], pre)))
    if profile in VERTEX_EDGES:
        for f, last in VERTEX_EDGES[profile].items():
            for n in (last, last + 1):
                pre = [f"dcl_texcoord{n % 8} v{n}"] if f == "v" and n != 0 else []
                out.append((f"reg-{f}{n}", vertex(profile, [VERTEX_REGS[f].format(n)], pre)))
    return out


def limit_probes(profile):
    """Straight-line code at and past the documented limits."""
    out = []
    if profile.startswith("ps_2"):
        t = "t0"
        for n in (63, 64, 65, 96, 97, 512, 513):
            out.append((f"limit-arith-{n}", pixel(profile, ["add r0, r0, c0"] * (n - 4))))
        # texkill reads t0 and writes nothing: no dependent reads, only texture slots
        for n in (32, 33):
            out.append((f"limit-tex-{n}", pixel(profile, [f"texkill {t}"] * n)))
        # dependent reads: each texld reads the coordinate the previous one wrote
        for n in (4, 5):
            body = [f"texld r3, {t}, s0"] + ["texld r3, r3, s0"] * (n - 1)
            out.append((f"limit-dependent-{n}", pixel(profile, body)))
    if profile.startswith("vs_2"):
        for n in (256, 257):
            out.append((f"limit-slots-{n}", vertex(profile, ["add r0, r0, c0"] * (n - 4))))
    return out


def rel_probes(profile):
    """Relative addressing in a vertex profile: `c[a0.x + n]`, `c[aL + n]`, vs_3_0's `v[aL + n]`
    and `o[aL + n]`, and the forms the assembler refuses (each probe's name says which)."""
    i0 = ["defi i0, 2, 0, 0, 0"]
    looped = lambda *body: ["loop aL, i0"] + list(body) + ["endloop"]
    mova = ["mova a0.x, r1.x"]
    out = [
        ("rel-c-a0", mova + ["mov r0, c[a0.x + 3]"], []),
        ("rel-c-a0-base", mova + ["mov r0, c2[a0.x + 3]"], []),
        ("rel-c-a0-y", ["mova a0.xy, r1", "mov r0, -c[a0.y + 1].yzxw"], []),
        ("rel-c-a0-w", ["mova a0, r1", "mul r0, r1, c[a0.w + 7].y"], []),
        ("rel-c-a0-unset", ["mov r0, c[a0.x]"], []),
        ("rel-c-offset-first", mova + ["mov r0, c[3 + a0.x]"], []),
        ("rel-c-offset-both", mova + ["mov r0, c[1 + a0.x + 2]"], []),
        ("rel-c-aL-offset-first", looped("add r0, r0, c[5 + aL]"), i0),
        ("rel-c-a0-nocomponent", mova + ["mov r0, c[a0 + 3]"], []),
        ("rel-c-a0-twocomponents", mova + ["mov r0, c[a0.xy + 3]"], []),
        ("rel-c-same", mova + ["add r0, c[a0.x + 3], c[a0.x + 3]"], []),
        ("rel-c-different", mova + ["add r0, c[a0.x + 3], c[a0.x + 4]"], []),
        ("rel-c-absolute", mova + ["add r0, c[a0.x + 3], c1"], []),
        ("rel-c-m4x4", mova + ["m4x4 r0, r1, c[a0.x + 4]"], []),
        ("rel-c-mova", ["mova a0.x, c[a0.x + 1].x"], []),
        ("rel-c-aL", looped("add r0, r0, c[aL + 5]"), i0),
        ("rel-c-aL-outside", ["mov r0, c[aL + 1]"], []),
        ("rel-c-aL-swizzle", looped("add r0, r0, c[aL.x + 5]"), i0),
        ("rel-c-aL-a0", mova + looped("add r0, c[aL + 5], c[a0.x + 5]"), i0),
        ("rel-r", mova + ["mov r0, r[a0.x + 1]"], []),
        ("rel-i", mova + ["rep i[a0.x]", "endrep"], i0),
        ("rel-v-aL", looped("add r0, r0, v[aL + 1]"), i0 + ["dcl_texcoord v1"]),
        ("rel-v-a0", mova + ["mov r0, v[a0.x + 1]"], ["dcl_texcoord v1"]),
        ("mova-dst-r", ["mova r0.x, r1.x"], []),
        ("read-a0-mov", mova + ["mov r0, a0"], []),
        ("read-a0-add", mova + ["add r0, r1, a0.x"], []),
    ]
    # Large constant files: bases from c2048 on are the register types CONST2-CONST4
    # (c2048-c8191); a larger base wraps at 8192, and a plain `c#` past c8191 is refused
    out += [
        ("rel-c-a0-2047", mova + ["mov r0, c[a0.x + 2047]"], []),
        ("rel-c-a0-2048", mova + ["mov r0, c[a0.x + 2048]"], []),
        ("rel-c-a0-4096", mova + ["mov r0, c[a0.x + 4096]"], []),
        ("rel-c-a0-6144", mova + ["mov r0, -c[a0.x + 6144].wzyx"], []),
        ("rel-c-a0-8191", mova + ["mov r0, c[a0.x + 8191]"], []),
        ("rel-c-a0-8195", mova + ["mov r0, c[a0.x + 8195]"], []),
        ("rel-c-a0-100000", mova + ["mov r0, c[a0.x + 100000]"], []),
        ("rel-c-base-2000", mova + ["mov r0, c2000[a0.x + 100]"], []),
        ("rel-c-aL-4100", looped("add r0, r0, c[aL + 4100]"), i0),
        ("rel-c-m4x4-8190", mova + ["m4x4 r0, r1, c[a0.x + 8190]"], []),
        ("rel-c-same-2050", mova + ["add r0, c[a0.x + 2050], c[a0.x + 2050]"], []),
        ("rel-c-absolute-2050", mova + ["add r0, c[a0.x + 2050], c2050"], []),
        ("const-3000", ["mov r0, c3000"], ["def c3000, 1, 2, 3, 4"]),
        ("const-8191", ["add r0, r1, c8191"], []),
        ("const-8192", ["mov r0, c8192"], []),
        ("const-def-8192", [], ["def c8192, 1, 2, 3, 4"]),
        ("const-two-large", ["add r0, c2050, c4000"], []),
    ]
    if profile != "vs_2_0":
        out.append(("rel-c-if", mova + ["if_gt c[a0.x].x, r1.x", "mov r0, r1", "endif"], []))
    if profile == "vs_3_0":
        outs = ["dcl_texcoord o1", "dcl_texcoord1 o2"]
        out += [
            ("rel-o-aL", looped("mov o[aL + 1], r1"), i0 + outs),
            ("rel-o-aL-mask", looped("mov o[aL + 1].xy, r1"), i0 + outs),
            ("rel-o-a0", mova + ["mov o[a0.x + 1], r1"], outs),
            ("rel-c-texldl", mova + ["texldl r0, c[a0.x], s0"], []),
            ("rel-c-texldl-4000", mova + ["texldl r0, c[a0.x + 4000], s0"], []),
            # an 11-bit register number: v[aL + 2048] is v0[aL]
            ("rel-v-aL-2048", looped("add r0, r0, v[aL + 2048]"), i0 + ["dcl_texcoord v1"]),
            ("rel-o-aL-2049", looped("mov o[aL + 2049], r1"), i0 + outs),
        ]
    sub = ["ret", "label l0", "add r0, r0, c[aL + 1]", "ret"]
    return [(name, vertex(profile, body, pre)) for name, body, pre in out] + [
        ("rel-c-aL-subroutine", vertex(profile, looped("call l0"), i0, sub)),
    ]


def operand_probes(profile):
    """Two different constants in one instruction, and matrix rows at and past the end of
    their file: each profile numbers these refusals apart; a vertex shader's constants are
    not checked at all (c8190's rows run past c8191 and are accepted)."""
    t = {"ps_3_0": "v0", "ps_2_0": "t0", "ps_2_x": "t0"}.get(profile, "v0")
    if profile.startswith("ps"):
        last = 224 if profile == "ps_3_0" else 32
        cases = [
            ("const-two", ["add r0, c1, c2"], []),
            (f"matrix-c{last - 4}", [f"m4x4 r0, {t}, c{last - 4}"], []),
            (f"matrix-c{last - 2}", [f"m4x4 r0, {t}, c{last - 2}"], []),
        ]
        return [(n, pixel(profile, b, p)) for n, b, p in cases]
    last = 12 if profile == "vs_2_0" else 32
    rows = lambda first: [f"mov r{k}, c0" for k in range(first, min(first + 4, last))]
    cases = [
        ("const-two", ["add r0, c1, c2"], []),
        ("matrix-c254", ["m4x4 r0, v0, c254"], []),
        (f"matrix-r{last - 4}", rows(last - 4) + [f"m4x4 r0, v0, r{last - 4}"], []),
        (f"matrix-r{last - 2}", rows(last - 2) + [f"m4x4 r0, v0, r{last - 2}"], []),
    ]
    return [(n, vertex(profile, b, p)) for n, b, p in cases]


def nest_probes(profile):
    """Flow-control nesting at and past each depth, within a function and through calls
    (Microsoft's validator counts a subroutine's blocks on top of those around its call),
    with `break_comp` and `callnz p0` counting as dynamic levels."""
    make = pixel if profile.startswith("ps") else vertex
    pre = ["defi i0, 2, 0, 0, 0", "defb b0, true"]
    nest = lambda n, head, tail, *body: [head] * n + list(body) + [tail] * n
    sub = lambda *body: ["ret", "label l0"] + list(body) + ["ret"]
    ifc, ifp, ifb = "if_gt r1.x, r2.x", "if p0.x", "if b0"
    setp = ["setp_gt p0, r1, r2"]
    add = "add r0, r0, c0"

    def chain(n):
        """main calls l0, which calls l1, ...: n calls deep."""
        post = []
        for k in range(n):
            post += ["ret", f"label l{k}", f"call l{k + 1}" if k < n - 1 else add]
        return ["call l0"], post + ["ret"]

    loops = 1 if profile == "vs_2_0" else 4
    cases = [
        (f"nest-rep-{loops + 1}", nest(loops + 1, "rep i0", "endrep", add), []),
        (f"nest-rep-{loops}-call", nest(loops, "rep i0", "endrep", "call l0"), sub(add)),
        (f"nest-rep-{loops}-call-rep", nest(loops, "rep i0", "endrep", "call l0"),
         sub("rep i0", add, "endrep")),
        ("nest-ifb-25", nest(25, ifb, "endif", add), []),
        ("nest-ifb-24-call-ifb", nest(24, ifb, "endif", "call l0"), sub(ifb, add, "endif")),
        ("nest-ifb-23-call-ifb", nest(23, ifb, "endif", "call l0"), sub(ifb, add, "endif")),
    ]
    for n in (loops, loops + 1):
        body, post = chain(n)
        cases.append((f"nest-calls-{n}", body, post))
    if profile != "vs_2_0":
        cases += [
            ("nest-ifc-25", nest(25, ifc, "endif", add), []),
            ("nest-ifp-25", setp + nest(25, ifp, "endif", add), []),
            ("nest-ifc-24-call-ifc", nest(24, ifc, "endif", "call l0"), sub(ifc, add, "endif")),
            ("nest-ifc-23-call-ifc", nest(23, ifc, "endif", "call l0"), sub(ifc, add, "endif")),
            ("nest-ifp-24-call-ifp", setp + nest(24, ifp, "endif", "call l0"),
             sub(ifp, add, "endif")),
            ("nest-breakc-24", ["rep i0"] + nest(24, ifc, "endif", "break_gt r1.x, r2.x")
             + ["endrep"], []),
            ("nest-breakc-23", ["rep i0"] + nest(23, ifc, "endif", "break_gt r1.x, r2.x")
             + ["endrep"], []),
            ("nest-callnzp-24", setp + nest(24, ifc, "endif", "callnz l0, p0.x"), sub(add)),
            ("nest-callnzp-23-call-ifc", setp + nest(23, ifc, "endif", "callnz l0, p0.x"),
             sub(ifc, add, "endif")),
            ("nest-callnzp-22-call-ifc", setp + nest(22, ifc, "endif", "callnz l0, p0.x"),
             sub(ifc, add, "endif")),
        ]
    return [(name, make(profile, body, pre, post)) for name, body, post in cases]


def probes():
    """(relative path, text) of every probe, in a fixed order."""
    out = []
    for profile in PIXEL + VERTEX:
        make = pixel if profile.startswith("ps") else vertex
        out.append((f"{profile}/base.psh", make(profile, [])))
        for name, body, pre, post in ops(profile):
            out.append((f"{profile}/op-{name}.psh", make(profile, body, pre, post)))
        for name, text in reg_probes(profile) + limit_probes(profile):
            out.append((f"{profile}/{name}.psh", text))
        for name, text in operand_probes(profile):
            out.append((f"{profile}/{name}.psh", text))
        if profile != "ps_2_0":
            for name, text in nest_probes(profile):
                out.append((f"{profile}/{name}.psh", text))
        if profile in VERTEX:
            for name, text in rel_probes(profile):
                out.append((f"{profile}/{name}.psh", text))
        if profile == "ps_3_0":
            # the 11-bit register number of v[aL + n]: v[aL + 2048] is v0[aL]
            body = ["loop aL, i0", "add r0, r0, v[aL + 2048]", "endloop"]
            out.append((f"{profile}/rel-v-aL-2048.psh", pixel(profile, body, ["defi i0, 2, 0, 0, 0"])))
    # ps_1_x: another instruction set, its own probes (ps1_probes.py)
    for profile in ps1_probes.PS1:
        for name, text in ps1_probes.probes(profile):
            out.append((f"{profile}/{name}.psh", text))
    for profile in OLD:
        if profile.startswith("ps"):
            text = pixel(profile, [])
        else:
            text = f"{profile}\ndcl_position v0\nmov oPos, v0\n"
        out.append((f"{profile}/base.psh", text))
    return out


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    default = os.path.join(here, "..", "..", "tests", "oracle", "corpus", "asm", "profiles")
    ap = argparse.ArgumentParser(description="Writes the per-profile oracle probes.")
    ap.add_argument("--out", default=os.path.normpath(default))
    args = ap.parse_args()
    for dirpath, _dirs, files in os.walk(args.out):
        for f in files:
            if f.endswith(".psh"):
                os.remove(os.path.join(dirpath, f))
    written = 0
    for rel, text in probes():
        path = os.path.join(args.out, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="ascii", newline="\n") as f:
            f.write(text)
        written += 1
    print(f"{written} profile probes in {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
