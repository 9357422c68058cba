"""The ps_1_1-ps_1_4 probes of tools/oracle/profile_probes.py (one list per profile).

ps_1_x is another instruction set: texture-addressing instructions writing t# (ps_1_1-ps_1_3),
`texld`/`texcrd` into r# with a `phase` marker (ps_1_4), co-issued pairs (`+`), source
modifiers (`_bias`, `_bx2`, `_x2`, `1-`, `_dz`/`_dw`) and instruction modifiers (`_x2` ...
`_d8`, `_sat`). Every probe is a whole shader; its name says what it holds:

* `op-NAME`: one instruction with what it needs around it (the texture coordinates it reads,
  the pads of the texm3x* family, a phase marker for what only phase 2 allows);
* `src-NAME`, `dst-NAME`, `mod-NAME`, `sel-NAME`: one source modifier, write mask,
  instruction modifier or source selector;
* `pair-NAME`: co-issue, good and bad;
* `reg-FILEN`: a register at the edge of its file (the last one and the one past it);
* `limit-*`: straight-line code at and past the slot limits;
* `bad-NAME`: a rule Microsoft's assembler enforces.

Standard library only.
"""

PS1 = ["ps_1_1", "ps_1_2", "ps_1_3", "ps_1_4"]
DEFS = ["def c0, 1, 0.5, 0.25, 0", "def c1, -1, 0, 0.5, 1"]


def old(profile, tex=(), arith=()):
    """A ps_1_1-ps_1_3 shader: texture instructions, then r0 and r1 set, then `arith`."""
    lines = [profile] + DEFS + list(tex) + ["mov r0, c0", "mov r1, c1"] + list(arith)
    return "\n".join(lines) + "\n"


def new(profile, tex=(), arith=(), tex2=None, arith2=()):
    """A ps_1_4 shader: phase 1 (texture, r0 and r1 set, `arith`), then, when `tex2` is not
    None, a phase marker, phase 2's texture instructions, r0 set again and `arith2`."""
    lines = [profile] + DEFS + list(tex) + ["mov r0, c0", "mov r1, c1"] + list(arith)
    if tex2 is not None:
        lines += ["phase"] + list(tex2) + ["mov r0, c0"] + list(arith2)
    return "\n".join(lines) + "\n"


def texture_ops_old(p):
    """(name, text) of the texture-addressing instructions in ps_1_1-ps_1_3 form."""
    m32 = ["tex t0", "texm3x2pad t1, t0"]
    m33 = ["tex t0", "texm3x3pad t1, t0", "texm3x3pad t2, t0"]
    return [
        ("op-tex", old(p, ["tex t0"], ["add r0, r0, t0"])),
        ("op-tex-t3", old(p, ["tex t3"], ["add r0, r0, t3"])),
        ("op-texcoord", old(p, ["texcoord t0"], ["add r0, r0, t0"])),
        ("op-texkill", old(p, ["texkill t0"])),
        ("op-texbem", old(p, ["tex t0", "texbem t1, t0"], ["add r0, r0, t1"])),
        ("op-texbeml", old(p, ["tex t0", "texbeml t1, t0"], ["add r0, r0, t1"])),
        ("op-texreg2ar", old(p, ["tex t0", "texreg2ar t1, t0"], ["add r0, r0, t1"])),
        ("op-texreg2gb", old(p, ["tex t0", "texreg2gb t1, t0"], ["add r0, r0, t1"])),
        ("op-texreg2rgb", old(p, ["tex t0", "texreg2rgb t1, t0"], ["add r0, r0, t1"])),
        ("op-texm3x2tex", old(p, m32 + ["texm3x2tex t2, t0"], ["add r0, r0, t2"])),
        ("op-texm3x2tex-bx2", old(p, ["tex t0", "texm3x2pad t1, t0_bx2",
                                      "texm3x2tex t2, t0_bx2"], ["add r0, r0, t2"])),
        ("op-texm3x2depth", old(p, m32 + ["texm3x2depth t2, t0"])),
        ("op-texm3x3tex", old(p, m33 + ["texm3x3tex t3, t0"], ["add r0, r0, t3"])),
        ("op-texm3x3spec", old(p, m33 + ["texm3x3spec t3, t0, c0"], ["add r0, r0, t3"])),
        ("op-texm3x3vspec", old(p, m33 + ["texm3x3vspec t3, t0"], ["add r0, r0, t3"])),
        ("op-texm3x3", old(p, m33 + ["texm3x3 t3, t0"], ["add r0, r0, t3"])),
        ("op-texdp3", old(p, ["tex t0", "texdp3 t1, t0"], ["add r0, r0, t1"])),
        ("op-texdp3tex", old(p, ["tex t0", "texdp3tex t1, t0"], ["add r0, r0, t1"])),
        ("op-texld", old(p, ["texld t0, t0"])),
        ("op-texcrd", old(p, ["texcrd r1, t0"])),
        ("op-texdepth", old(p, ["texdepth r0"])),
        ("bad-pad-alone", old(p, ["tex t0", "texm3x2pad t1, t0"])),
        ("bad-pad-read", old(p, m32 + ["texm3x2tex t2, t0"], ["add r0, r0, t1"])),
        ("bad-tex-twice", old(p, ["tex t0", "tex t0"])),
        ("bad-tex-after-arith", old(p, [], ["tex t0"])),
        ("bad-texbem-order", old(p, ["tex t1", "texbem t0, t1"])),
        ("bad-texcoord-source", old(p, ["texcoord t0, t1"])),
        ("mod-tex-x2", old(p, ["tex_x2 t0"], ["add r0, r0, t0"])),
        ("mod-tex-sat", old(p, ["tex_sat t0"], ["add r0, r0, t0"])),
        ("mod-texbem-d4", old(p, ["tex t0", "texbem_d4 t1, t0"], ["add r0, r0, t1"])),
    ]


def texture_ops_new(p):
    """(name, text) of the ps_1_4 texture instructions."""
    return [
        ("op-texld", new(p, ["texld r2, t0"], ["add r0, r0, r2"])),
        ("op-texld-t5", new(p, ["texld r2, t5"], ["add r0, r0, r2"])),
        ("op-texld-dz", new(p, ["texld r2, t0_dz"], ["add r0, r0, r2"])),
        ("op-texld-dw", new(p, ["texld r2, t0_dw.xyw"], ["add r0, r0, r2"])),
        ("op-texld-temp", new(p, ["texcrd r2.rgb, t0"], [], ["texld r3, r2"], ["add r0, r0, r3"])),
        ("op-texld-temp-dz", new(p, ["texcrd r2.rgb, t0"], [], ["texld r3, r2_dz"],
                                 ["add r0, r0, r3"])),
        ("op-texld-temp-db", new(p, ["texcrd r2.rgb, t0"], [], ["texld r3, r2_db"],
                                 ["add r0, r0, r3"])),
        ("op-texld-phase2", new(p, [], [], ["texld r2, t0"], ["add r0, r0, r2"])),
        ("op-texld-xyw", new(p, ["texld r2, t0.xyw"], ["add r0, r0, r2"])),
        ("op-texcrd", new(p, ["texcrd r2.rgb, t0"], ["add r0.rgb, r0, r2"])),
        ("op-texcrd-xyw", new(p, ["texcrd r2.rgb, t0.xyw"], ["add r0.rgb, r0, r2"])),
        ("op-texcrd-dw", new(p, ["texcrd r2.rgb, t0_dw.xyw"], ["add r0.rgb, r0, r2"])),
        ("op-texcrd-da", new(p, ["texcrd r2.rgb, t0_da.xyw"], ["add r0.rgb, r0, r2"])),
        ("op-texcrd-rg", new(p, ["texcrd r2.rg, t0"], ["add r0.rg, r0, r2"])),
        ("op-texcrd-all", new(p, ["texcrd r2, t0"], ["add r0, r0, r2"])),
        ("op-texkill", new(p, [], [], ["texkill t0"])),
        ("op-texkill-r", new(p, ["texcrd r2.rgb, t0"], [], ["texkill r2"])),
        ("op-texkill-phase1", new(p, ["texkill t0"])),
        ("op-texdepth", new(p, [], ["mov r5, c0"], ["texdepth r5"])),
        ("op-bem", new(p, ["texld r2, t0", "texcrd r3.rgb, t1"], ["bem r3.rg, c0, r2"],
                       ["texld r4, r3"], ["add r0, r0, r4"])),
        ("op-bem-nophase", new(p, ["texld r2, t0"], ["bem r3.rg, c0, r2"])),
        ("op-phase", new(p, ["texld r2, t0"], ["add r1, r1, r2"], ["texld r3, t1"],
                         ["add r0, r0, r3"])),
        ("op-tex", new(p, ["tex t0"])),
        ("op-texcoord", new(p, ["texcoord t0"])),
        ("op-texbem", new(p, ["texld r0, t0", "texbem t1, t0"])),
        ("op-texreg2ar", new(p, ["texld r0, t0", "texreg2ar t1, t0"])),
        ("op-texm3x2pad", new(p, ["texm3x2pad t1, t0"])),
        ("op-texm3x3pad", new(p, ["texm3x3pad t1, t0"])),
        ("op-texdp3", new(p, ["texdp3 t1, t0"])),
        ("bad-phase-twice", new(p, [], [], [], ["phase"])),
        ("bad-texld-after-arith", new(p, [], ["texld r2, t0"])),
        ("bad-texld-same-twice", new(p, ["texld r2, t0", "texld r2, t1"])),
        ("bad-texld-swizzle", new(p, ["texld r2, t0.wzyx"])),
        ("bad-texld-temp-phase1", new(p, ["texld r2, r1"])),
        ("bad-dz-on-t", new(p, ["texld r2, t0_dz"], [], [], [])),
        ("bad-dz-twice", new(p, [], [], ["texld r2, t0_dz"], [])),
        ("bad-alpha-after-phase", new(p, [], ["mov r2, c0"], [], ["add r0, r0, r2.a"])),
        ("bad-texcrd-read-w", new(p, ["texcrd r2.rgb, t0"], ["add r0, r0, r2.a"])),
        ("mod-texld-x2", new(p, ["texld_x2 r2, t0"], ["add r0, r0, r2"])),
        ("mod-texcrd-sat", new(p, ["texcrd_sat r2.rgb, t0"], ["add r0.rgb, r0, r2"])),
        ("mod-texdepth-x2", new(p, [], ["mov r5, c0"], ["texdepth_x2 r5"])),
        ("mod-bem-d2", new(p, ["texld r2, t0", "texcrd r3.rgb, t1"], ["bem_d2 r3.rg, c0, r2"],
                           ["texld r4, r3"], ["add r0, r0, r4"])),
        ("mod-bem-sat", new(p, ["texld r2, t0", "texcrd r3.rgb, t1"], ["bem_sat r3.rg, c0, r2"],
                            ["texld r4, r3"], ["add r0, r0, r4"])),
    ]


def arithmetic(p, make):
    """(name, text) of the arithmetic, its modifiers, selectors, masks and co-issue."""
    a = lambda *lines: make(p, [], list(lines))  # noqa: E731
    out = [
        ("base", a()),
        ("op-mov", a("mov r0, r1")),
        ("op-add", a("add r0, r0, r1")),
        ("op-sub", a("sub r0, r0, r1")),
        ("op-mul", a("mul r0, r0, r1")),
        ("op-mad", a("mad r0, r0, r1, c0")),
        ("op-dp3", a("dp3 r0, r0, r1")),
        ("op-dp3-alpha", a("dp3 r0.a, r0, r1")),
        ("op-dp4", a("dp4 r0, r1, c0")),
        ("op-dp4-same", a("dp4 r0, r0, c0")),
        ("op-lrp", a("lrp r0, c0, r0, r1")),
        ("op-cnd", a("cnd r0, r0.a, r1, c0")),
        ("op-cnd-any", a("cnd r0, r1, r0, c0")),
        ("op-cmp", a("cmp r0, r1, c0, c1")),
        ("op-cmp-same", a("cmp r0, r0, r1, c0")),
        ("op-nop", a("nop")),
        ("op-def-range", make(p, [], []).replace("def c1, -1, 0, 0.5, 1", "def c1, -2, 0, 1.5, 8")),
        ("op-def-after", a("def c2, 0, 0, 0, 0")),
        ("src-neg", a("add r0, r0, -r1")),
        ("src-bias", a("add r0, r0, r1_bias")),
        ("src-negbias", a("add r0, r0, -r1_bias")),
        ("src-bx2", a("add r0, r0, r1_bx2")),
        ("src-negbx2", a("add r0, r0, -r1_bx2")),
        ("src-comp", a("add r0, r0, 1-r1")),
        ("src-comp-space", a("add r0, r0, 1 - r1")),
        ("src-x2", a("add r0, r0, r1_x2")),
        ("src-negx2", a("add r0, r0, -r1_x2")),
        ("src-abs", a("add r0, r0, r1_abs")),
        ("src-bias-const", a("add r0, r0, c1_bias")),
        ("src-bx2-lrp", a("lrp r0, c0, r0, r1_bx2")),
        ("src-comp-lrp", a("lrp r0, 1-c0, r0, r1")),
        ("sel-r", a("add r0, r0, r1.r")),
        ("sel-g", a("add r0, r0, r1.g")),
        ("sel-b", a("add r0, r0, r1.b")),
        ("sel-a", a("add r0, r0, r1.a")),
        ("sel-x", a("add r0, r0, r1.x")),
        ("sel-w", a("add r0, r0, r1.w")),
        ("sel-swizzle", a("add r0, r0, r1.gbra")),
        ("sel-a-bx2", a("add r0, r0, -r1_bx2.a")),
        ("dst-rgb", a("add r0.rgb, r0, r1")),
        ("dst-a", a("add r0.a, r0, r1")),
        ("dst-xyz", a("add r0.xyz, r0, r1")),
        ("dst-rg", a("add r0.rg, r0, r1")),
        ("dst-r", a("add r0.r, r0, r1")),
        ("dst-gb", a("add r0.gb, r0, r1")),
        ("dst-t", a("add t0, r0, r1")),
        ("pair", a("mul r0.rgb, r0, r1", "+add r0.a, r1, c0")),
        ("pair-space", a("mul r0.rgb, r0, r1", "+ add r0.a, r1, c0")),
        ("pair-other-reg", a("mul r0.rgb, r0, r1", "+mov r1.a, c0")),
        ("pair-alpha-first", a("mov r1.a, c0", "+mul r0.rgb, r0, r1")),
        ("pair-mods", a("mul_x2 r0.rgb, r0_bx2, 1-r1", "+add_sat r0.a, r1_bias, -r0")),
        ("pair-dp3", a("dp3 r0.rgb, r0, r1", "+mov r0.a, c0")),
        ("pair-both-rgb", a("mul r0.rgb, r0, r1", "+add r0.rgb, r1, c0")),
        ("pair-all", a("mul r0, r0, r1", "+add r0.a, r1, c0")),
        ("pair-first", make(p, [], []).replace("mov r1, c1", "+mov r1, c1")),
        ("pair-three", a("mul r0.rgb, r0, r1", "+add r0.a, r1, c0", "+add r1.a, r1, c0")),
        ("pair-lrp", a("lrp r0.rgb, c0, r0, r1", "+mov r0.a, c0")),
        ("pair-cnd", a("cnd r0.rgb, r0.a, r1, c0", "+mov r0.a, c0")),
        ("pair-nop", a("nop", "+mov r0.a, c0")),
        ("bad-uninit", a("add r0, r0, r3" if p == "ps_1_4" else "add r0, r0, t0")),
        ("bad-write-v", a("mov v0, c0")),
        ("bad-write-c", a("mov c0, r0")),
        ("bad-two-consts", a("mad r0, c0, c1, r1")),
        ("bad-three-v", a("mad r0, v0, v1, r1")),
        ("bad-no-r0", "\n".join([p] + DEFS + ["mov r1, c1"]) + "\n"),
        ("bad-unknown-mod", a("add_x3 r0, r0, r1")),
        ("bad-sat-twice", a("add_sat_sat r0, r0, r1")),
    ]
    for m in ["x2", "x4", "x8", "d2", "d4", "d8", "sat", "x2_sat", "d8_sat", "pp"]:
        out.append((f"mod-{m.replace('_', '-')}", a(f"add_{m} r0, r0, r1")))
    return out


def registers(p):
    """(name, text) at the edge of each register file."""
    make = new if p == "ps_1_4" else old
    temps, tcoords = (5, 5) if p == "ps_1_4" else (1, 3)
    out = []
    for n in (temps, temps + 1):
        out.append((f"reg-r{n}", make(p, [], [f"mov r{n}, c0", f"add r0, r0, r{n}"])))
    for n in (7, 8):
        out.append((f"reg-c{n}", make(p, [], [f"add r0, r0, c{n}"])))
    for n in (1, 2):
        out.append((f"reg-v{n}", make(p, [], [f"add r0, r0, v{n}"])))
    for n in (tcoords, tcoords + 1):
        if p == "ps_1_4":
            out.append((f"reg-t{n}", make(p, [f"texld r2, t{n}"], ["add r0, r0, r2"])))
        else:
            out.append((f"reg-t{n}", make(p, [f"tex t{n}"], [f"add r0, r0, t{n}"])))
    out.append(("reg-t-read", make(p, [], ["add r0, r0, t0"])))
    return out


def limits(p):
    """(name, text) of straight-line code at and past the slot limits."""
    out = []
    adds = lambda n: ["add r0, r0, c0"] * (n - 2)  # noqa: E731  (r0 and r1 set: 2 slots)
    if p == "ps_1_4":
        for n in (8, 9):
            out.append((f"limit-arith-{n}", new(p, [], adds(n))))
            out.append((f"limit-arith2-{n}", new(p, [], [], [], ["add r0, r0, c0"] * (n - 1))))
        for n in (6, 7):
            tex = [f"texld r{i}, t{i}" for i in range(min(n, 6))] + ["texld r5, t5"] * (n - 6)
            out.append((f"limit-tex-{n}", new(p, tex[:6] + (["texkill t0"] if n > 6 else []))))
            out.append((f"limit-tex2-{n}", new(p, [], [], tex[:6] + (["texkill t0"] if n > 6 else []))))
        out.append(("limit-pair-8", new(p, [], adds(8)[:-1] + ["add r0.rgb, r0, c0", "+add r0.a, r0, c0"])))
        out.append(("limit-both-phases", new(p, ["texld r2, t0"] * 1, adds(8), ["texld r3, t1"], adds(7))))
    else:
        for n in (8, 9):
            out.append((f"limit-arith-{n}", old(p, [], adds(n))))
        out.append(("limit-pair-8", old(p, [], adds(7) + ["add r0.rgb, r0, c0", "+add r0.a, r0, c0"])))
        for n in (4, 5):
            tex = [f"tex t{i}" for i in range(min(n, 4))] + (["texkill t0"] if n > 4 else [])
            out.append((f"limit-tex-{n}", old(p, tex)))
        out.append(("limit-both-12", old(p, [f"tex t{i}" for i in range(4)], adds(8))))
    return out


def probes(profile):
    """(name, text) of every ps_1_x probe of `profile`, in a fixed order."""
    make = new if profile == "ps_1_4" else old
    tex = texture_ops_new(profile) if profile == "ps_1_4" else texture_ops_old(profile)
    return arithmetic(profile, make) + tex + registers(profile) + limits(profile)
