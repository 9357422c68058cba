//! Float rules: what the special values of ps_3_0 arithmetic are, as one
//! named choice that the emulator and the translation share.
//!
//! Direct3D 9 defines a few results IEEE arithmetic would not give — the
//! log of 0 is −FLT_MAX, not −∞; `log` and `rsq` ignore the sign; `nrm`
//! of a zero vector scales by FLT_MAX — and leaves others to the hardware.
//! Translators made different choices (facts in
//! `reference/d3d9-translation-notes.md`): some follow Microsoft's pages,
//! some emit plain IEEE functions, some also force 0 × anything to 0 as
//! some D3D9 hardware did. ps30 names each set here once; the emulator
//! (`core/emu/math.rs`) computes by it and the translation
//! (`core/translate/`) emits code for it, only where a rule differs from
//! what the target language computes anyway. [`RULES`] is the table both
//! follow, with the source of every D3D9 rule.

use std::fmt;

/// A set of float rules. `Hardware` is the default everywhere (docs/float-rules.md
/// says why).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, serde::Serialize)]
pub enum FloatRules {
    /// Microsoft's instruction pages, IEEE everywhere else.
    D3d9,
    /// Plain IEEE 754 results: no absolute values, no clamps, no FLT_MAX.
    Ieee,
    /// `D3d9`, and a product with a zero factor is zero (0 × ∞ = 0,
    /// 0 × NaN = 0) in `mul`, `mad`, `lrp`, `dp2add`, `dp3`, `dp4`, the
    /// matrix instructions and `nrm`.
    D3d9ZeroMul,
    /// What native Direct3D 9 hardware computes: `D3d9ZeroMul`, and every
    /// denormal flushed to zero (of the same sign) where it enters the
    /// shader (constants, inputs, texture samples) and where an instruction
    /// writes it. See `docs/float-rules.md` for the evidence of each rule.
    #[default]
    Hardware,
}

impl FloatRules {
    /// Every set: the order reports list them in.
    pub const ALL: [FloatRules; 4] = [
        FloatRules::D3d9,
        FloatRules::Ieee,
        FloatRules::D3d9ZeroMul,
        FloatRules::Hardware,
    ];

    /// The name used on the command line and in reports.
    pub fn name(self) -> &'static str {
        match self {
            FloatRules::D3d9 => "d3d9",
            FloatRules::Ieee => "ieee",
            FloatRules::D3d9ZeroMul => "d3d9-zero-mul",
            FloatRules::Hardware => "hardware",
        }
    }

    /// The set a command-line or report name stands for ([`FloatRules::name`]);
    /// `None` for an unknown name, so the caller can list [`FloatRules::ALL`].
    pub fn from_name(name: &str) -> Option<FloatRules> {
        FloatRules::ALL.into_iter().find(|r| r.name() == name)
    }

    /// Whether the D3D9 special values apply (every set but `Ieee`).
    pub fn d3d9_specials(self) -> bool {
        self != FloatRules::Ieee
    }

    /// Whether a zero factor makes a product zero.
    pub fn zero_mul(self) -> bool {
        matches!(self, FloatRules::D3d9ZeroMul | FloatRules::Hardware)
    }

    /// Whether denormals are flushed to zero on the way in and out of every
    /// instruction (`hardware`).
    pub fn flush_denormals(self) -> bool {
        self == FloatRules::Hardware
    }
}

impl fmt::Display for FloatRules {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One rule: an instruction's special cases under `d3d9` and under `ieee`,
/// and where the D3D9 side comes from.
#[derive(Clone, Copy, Debug)]
pub struct Rule {
    /// The ps_3_0 instruction the rule is about (`log`, `rsq`, `nrm`, …).
    pub instruction: &'static str,
    /// Its special cases under `d3d9` (and `d3d9-zero-mul`), in shader terms.
    pub d3d9: &'static str,
    /// Its special cases under `ieee`: what the target language computes anyway.
    pub ieee: &'static str,
    /// Where the D3D9 side is written down (`MS` = Microsoft's instruction pages).
    pub source: &'static str,
}

/// The rules that differ between the sets (MS = learn.microsoft.com/
/// windows/win32/direct3dhlsl/). Everything else — `rcp` of 0 (±∞, the
/// `rcp` page and IEEE agree), `exp` overflow (+∞: the `exp` page's
/// `(float)pow(2, src)` rounds to infinity as IEEE does), comparisons,
/// `min`/`max`/`_sat` — is the same under every set.
pub const RULES: &[Rule] = &[
    Rule {
        instruction: "log",
        d3d9: "log2(|x|); log(0) = -FLT_MAX",
        ieee: "log2(x): log(0) = -inf, log of a negative = NaN",
        source: "MS log---ps",
    },
    Rule {
        instruction: "rsq",
        d3d9: "1/sqrt(|x|); rsq(0) = +inf",
        ieee: "1/sqrt(x): rsq of a negative = NaN",
        source: "MS rsq---ps",
    },
    Rule {
        instruction: "nrm",
        d3d9: "a zero xyz scales by FLT_MAX: xyz = 0, w = w * FLT_MAX",
        ieee: "scale 1/sqrt(0) = +inf: xyz = 0 * inf = NaN",
        source: "MS nrm---ps",
    },
    Rule {
        instruction: "pow",
        d3d9: "|a|^b: pow(0, 0) = 1, pow(0, b<0) = +inf, pow(a, 0) = 1",
        ieee: "powr(a, b) = exp2(b * log2(a)): NaN for a < 0 and for pow(0, 0)",
        source: "MS pow---ps (|src0|; its expansion exp(src1 * log(src0)) with log(0) = -FLT_MAX gives the zero cases)",
    },
    Rule {
        instruction: "frc",
        d3d9: "x - floor(x), at most the largest f32 below 1",
        ieee: "x - floor(x) (1.0 for tiny negative x)",
        source: "MS frc---ps (\"result in [0, 1)\")",
    },
    Rule {
        instruction: "mul, mad, lrp, dp2add, dp3, dp4, m#x#, nrm",
        d3d9: "IEEE products (0 * inf = NaN); d3d9-zero-mul: 0 * anything = 0",
        ieee: "IEEE products",
        source: "d3d9-zero-mul follows DXVK's d3d9.floatEmulation = Strict (src/dxso/dxso_compiler.cpp, emitMulOperand) and DXVK issue #2016",
    },
];

/// f32's largest finite value (D3D9's FLT_MAX).
pub const FLT_MAX: f32 = f32::MAX;

/// `x` with a denormal flushed to a zero of its sign (the `hardware`
/// rules' treatment of every value an instruction reads or writes).
#[inline(always)]
pub fn flush(x: f32) -> f32 {
    if x.is_subnormal() {
        0.0f32.copysign(x)
    } else {
        x
    }
}

/// A product's operand under the zero-multiply rule: `a`, or 0 when the
/// other factor `b` is zero (so that `a · b` is 0 whatever `a` is).
#[inline(always)]
pub fn zero_mul_operand(a: f32, b: f32) -> f32 {
    if b == 0.0 {
        0.0
    } else {
        a
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for r in FloatRules::ALL {
            assert_eq!(FloatRules::from_name(r.name()), Some(r));
        }
        assert_eq!(FloatRules::from_name("strict"), None);
        assert_eq!(FloatRules::default(), FloatRules::Hardware);
    }

    #[test]
    fn zero_mul_operands_make_zero_products() {
        let inf = f32::INFINITY;
        let p = zero_mul_operand(inf, 0.0) * zero_mul_operand(0.0, inf);
        assert_eq!(p, 0.0);
        let p = zero_mul_operand(f32::NAN, 0.0) * zero_mul_operand(0.0, f32::NAN);
        assert_eq!(p, 0.0);
        assert_eq!(zero_mul_operand(2.0, 3.0) * zero_mul_operand(3.0, 2.0), 6.0);
    }

    #[test]
    fn flush_keeps_sign_and_normals() {
        let tiny = f32::from_bits(1);
        assert_eq!(flush(tiny).to_bits(), 0);
        assert_eq!(flush(-tiny).to_bits(), 0x8000_0000);
        assert_eq!(flush(f32::MIN_POSITIVE), f32::MIN_POSITIVE);
        assert!(flush(f32::NAN).is_nan());
        assert_eq!(flush(f32::INFINITY), f32::INFINITY);
        assert!(FloatRules::Hardware.zero_mul() && FloatRules::Hardware.d3d9_specials());
    }
}
