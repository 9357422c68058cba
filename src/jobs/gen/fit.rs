//! Fitting blocks and pass-2 forms to a profile, by search over the real
//! cost model.
//!
//! Every predicate here loads a generated listing and asks
//! [`crate::core::cost::analyse`]; the searches only rely on the counts growing
//! with the block (more texels per line never cost fewer slots or executed
//! instructions, more lines never cost fewer executed instructions), which
//! holds for every listing `asm.rs` writes.
//!
//! The only shortcut is a sound lower bound used to avoid building absurd
//! listings: every `texld` costs at least one slot, so a listing with more
//! unrolled `texld`s than the slot limit cannot fit.

use super::asm::{self, Counts, Pass1Form, Pass2Form};
use super::{measure, Checked, GenError};
use crate::core::cost::{Environment, Profile};
use crate::core::isa::MAX_REP_COUNT;
use crate::core::load;
use crate::core::numbers::thousands;
use std::collections::HashMap;

/// The pass-2 listing chosen for an intermediate target.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Pass2Choice {
    pub form: Pass2Form,
    pub targets: (u32, u32),
    pub slots: u64,
    pub executed: u64,
}

/// What was tried for a pass 2, and what fits.
#[derive(Clone, Debug, PartialEq)]
pub struct Pass2Outcome {
    /// The first form (fewest executed instructions) that fits, if any.
    pub choice: Option<Pass2Choice>,
    /// Why each form that does not fit was rejected, in numbers.
    pub rejected: Vec<String>,
}

/// Measures generated listings under one profile, caching what it loaded.
pub struct Fitter<'p> {
    profile: &'p Profile,
    pass1: HashMap<(Pass1Form, u32), load::Loaded>,
    pass2: HashMap<(u32, u32), Pass2Outcome>,
}

fn rep_ok(n: u32) -> bool {
    n as i64 <= MAX_REP_COUNT as i64
}

impl<'p> Fitter<'p> {
    pub fn new(profile: &'p Profile) -> Fitter<'p> {
        Fitter {
            profile,
            pass1: HashMap::new(),
            pass2: HashMap::new(),
        }
    }

    pub fn profile(&self) -> &Profile {
        self.profile
    }

    /// Why pass 1 in `form` with `taps` texels per line cannot even be
    /// written under the profile, if so.
    pub fn pass1_unwritable(&self, form: Pass1Form, taps: u32, rows: u32) -> Option<String> {
        let p = self.profile;
        if taps == 0 || rows == 0 {
            return Some("a block side is 0".into());
        }
        if form.nesting() > p.max_loop_nesting {
            return Some(format!(
                "the {} form nests loops {} deep; the profile allows {}",
                form.name(),
                form.nesting(),
                p.max_loop_nesting
            ));
        }
        if !rep_ok(rows) || rows > p.max_rep_count {
            return Some(format!(
                "{} need a rep count of {rows}; the profile allows 0 to {}",
                crate::core::numbers::plural(rows as u64, "line", "lines"),
                p.max_rep_count
            ));
        }
        match form {
            Pass1Form::Loop if !rep_ok(taps) || taps > p.max_rep_count => Some(format!(
                "{taps} texels per line need a rep count of {taps}; the profile allows 0 to {}",
                p.max_rep_count
            )),
            Pass1Form::Unrolled if taps as u64 > p.max_slots => Some(format!(
                "unrolling {taps} texels per line takes at least {taps} texld slots; the limit is {}",
                thousands(p.max_slots)
            )),
            _ => None,
        }
    }

    /// Pass 1 in `form` for a `taps × rows` block, measured (None when it
    /// cannot be written under the profile: see [`Self::pass1_unwritable`]).
    pub fn pass1(
        &mut self,
        form: Pass1Form,
        taps: u32,
        rows: u32,
    ) -> Result<Option<Checked>, GenError> {
        if self.pass1_unwritable(form, taps, rows).is_some() {
            return Ok(None);
        }
        let profile = self.profile;
        let loaded = match self.pass1.entry((form, taps)) {
            std::collections::hash_map::Entry::Occupied(e) => e.into_mut(),
            std::collections::hash_map::Entry::Vacant(e) => {
                let text = asm::render(&asm::pass1(form, taps, 1, Counts::Application), true);
                let name = format!("pass1_{}_{taps}", form.name());
                e.insert(super::load(&name, &text, profile)?)
            }
        };
        let mut env = Environment::default();
        env.ints.insert(1, [taps as i32, 0, 0, 0]);
        env.ints.insert(2, [rows as i32, 0, 0, 0]);
        measure(loaded, &env, profile).map(Some)
    }

    /// The widest block (texels per line) of `form`, at most `cap`, whose
    /// one-line block fits the profile.
    pub fn widest(&mut self, form: Pass1Form, cap: u32) -> Result<Option<u32>, GenError> {
        let cap = match form {
            Pass1Form::Loop => cap.min(self.profile.max_rep_count),
            Pass1Form::Unrolled => cap.min(self.profile.max_slots.min(u32::MAX as u64) as u32),
        };
        self.largest(cap, |f, taps| f.pass1(form, taps, 1))
    }

    /// The tallest block (lines), at most `cap`, of `form` with `taps`
    /// texels per line that fits the profile.
    pub fn tallest(
        &mut self,
        form: Pass1Form,
        taps: u32,
        cap: u32,
    ) -> Result<Option<u32>, GenError> {
        let cap = cap.min(self.profile.max_rep_count);
        self.largest(cap, |f, rows| f.pass1(form, taps, rows))
    }

    /// The largest n in 1..=cap whose measured listing fits, for listings
    /// that fit up to some n and not beyond.
    ///
    /// The answer is found by measuring, never by formula: n = 1 and 2 give
    /// the counts' growth, a straight line through them guesses the last n
    /// within the limits, and the guess is taken only when it fits and the
    /// next n does not. Otherwise (counts that do not grow in a straight
    /// line) a bisection between what was learnt finishes the search. The
    /// generated listings grow in a straight line, so this takes four
    /// measurements where bisection alone took about ten.
    fn largest(
        &mut self,
        cap: u32,
        mut measure: impl FnMut(&mut Self, u32) -> Result<Option<Checked>, GenError>,
    ) -> Result<Option<u32>, GenError> {
        let fits = |c: &Option<Checked>| c.as_ref().is_some_and(Checked::fits);
        if cap == 0 {
            return Ok(None);
        }
        let one = measure(self, 1)?;
        if !fits(&one) {
            return Ok(None);
        }
        // fits(lo); !fits(hi), or hi = cap + 1 when nothing above lo is known
        // not to fit.
        let (mut lo, mut hi) = (1u32, cap.saturating_add(1));
        if cap >= 2 {
            let two = measure(self, 2)?;
            if !fits(&two) {
                return Ok(Some(1));
            }
            lo = 2;
            let guess = self.straight_line(&one, &two).clamp(2, cap);
            if guess > lo {
                if fits(&measure(self, guess)?) {
                    lo = guess;
                } else {
                    hi = guess;
                }
            }
            if lo == guess && guess < cap {
                if fits(&measure(self, guess + 1)?) {
                    lo = guess + 1;
                } else {
                    hi = guess + 1;
                }
            }
        }
        if hi == cap.saturating_add(1) && lo < cap {
            if fits(&measure(self, cap)?) {
                return Ok(Some(cap));
            }
            hi = cap;
        }
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if fits(&measure(self, mid)?) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Ok(Some(lo))
    }

    /// The last n at which counts growing in a straight line through the
    /// measurements at n = 1 and n = 2 stay within the profile's slot and
    /// executed limits (a guess; `u32::MAX` when they do not grow).
    fn straight_line(&self, one: &Option<Checked>, two: &Option<Checked>) -> u32 {
        let (Some(one), Some(two)) = (one, two) else {
            return u32::MAX;
        };
        let last = |at1: u64, at2: u64, limit: u64| match at2.checked_sub(at1) {
            Some(step) if step > 0 => 1 + limit.saturating_sub(at1) / step,
            _ => u64::MAX,
        };
        let p = self.profile;
        last(one.slots, two.slots, p.max_slots)
            .min(last(one.executed, two.executed, p.max_executed))
            .min(u32::MAX as u64) as u32
    }

    /// The pass-2 listing for an `nx × ny` target: the first of unrolled,
    /// row loop and nested loops (fewest executed first) that fits.
    pub fn pass2(&mut self, nx: u32, ny: u32) -> Result<Pass2Outcome, GenError> {
        if let Some(o) = self.pass2.get(&(nx, ny)) {
            return Ok(o.clone());
        }
        let p = self.profile;
        let mut rejected = Vec::new();
        let mut choice = None;
        let taps = nx as u64 * ny as u64;
        for form in Pass2Form::ALL {
            let why_not = if form.nesting() > p.max_loop_nesting {
                Some(format!(
                    "needs loops nested {} deep; the profile allows {}",
                    form.nesting(),
                    p.max_loop_nesting
                ))
            } else {
                match form {
                    Pass2Form::Unrolled if taps > p.max_slots => Some(format!(
                        "{} texld slots at least, over the limit of {}",
                        thousands(taps),
                        thousands(p.max_slots)
                    )),
                    Pass2Form::RowLoop if !rep_ok(ny) || ny > p.max_rep_count => Some(format!(
                        "{ny} rows need a rep count of {ny}; the profile allows 0 to {}",
                        p.max_rep_count
                    )),
                    Pass2Form::RowLoop if nx as u64 > p.max_slots => Some(format!(
                        "a row of {nx} texld slots at least, over the limit of {}",
                        thousands(p.max_slots)
                    )),
                    Pass2Form::Nested if !rep_ok(nx.max(ny)) || nx.max(ny) > p.max_rep_count => {
                        Some(format!(
                            "{nx} × {ny} needs rep counts up to {}; the profile allows 0 to {}",
                            nx.max(ny),
                            p.max_rep_count
                        ))
                    }
                    _ => None,
                }
            };
            if let Some(w) = why_not {
                rejected.push(format!("{}: {w}", form.name()));
                continue;
            }
            let text = asm::render(&asm::pass2(form, nx, ny), true);
            let c = super::check(&format!("pass2_{nx}x{ny}"), &text, p)?;
            if c.fits() {
                choice = Some(Pass2Choice {
                    form,
                    targets: (nx, ny),
                    slots: c.slots,
                    executed: c.executed,
                });
                break;
            }
            rejected.push(format!("{}: {}", form.name(), c.problems.join("; ")));
        }
        let outcome = Pass2Outcome { choice, rejected };
        self.pass2.insert((nx, ny), outcome.clone());
        Ok(outcome)
    }
}

/// The height that covers `frame_h` with as many block rows as `tallest`
/// does, with the least padding: ⌈H / ⌈H / tallest⌉⌉ (never taller).
pub fn balanced(frame: u32, tallest: u32) -> u32 {
    let n = frame.div_ceil(tallest.max(1));
    frame.div_ceil(n.max(1))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Slots and executed instructions as functions of n.
    type Growth = fn(u64) -> (u64, u64);

    /// Counts as a function of n, with the profile's problems when over.
    fn counted(p: &Profile, slots: u64, executed: u64) -> Option<Checked> {
        let mut problems = Vec::new();
        if slots > p.max_slots {
            problems.push("slots".into());
        }
        if executed > p.max_executed {
            problems.push("executed".into());
        }
        Some(Checked {
            slots,
            executed,
            nesting: 0,
            max_rep: 0,
            problems,
        })
    }

    /// The search from a guess finds what trying every n finds, whether the
    /// counts grow in a straight line (the guess is right), in steps, or
    /// faster than a line (the guess is wrong and bisection finishes), and
    /// at every cap.
    #[test]
    fn the_search_finds_what_trying_every_n_finds() {
        let p = Profile::ps_3_0();
        let growths: [(&str, Growth); 5] = [
            ("straight", |n| (3 + 4 * n, 6 + 506 * n)),
            ("flat slots", |n| (9, 1 + 300 * n)),
            ("steps", |n| (3 + 4 * (n / 7) * 7, 10 * n)),
            ("faster", |n| (n * n, n)),
            ("never fits", |n| (600 + n, n)),
        ];
        for (name, growth) in growths {
            for cap in [0, 1, 2, 3, 50, 127, 128, 129, 600, 1024] {
                let brute = (1..=cap)
                    .take_while(|&n| {
                        counted(&p, growth(n as u64).0, growth(n as u64).1)
                            .unwrap()
                            .fits()
                    })
                    .last();
                let mut f = Fitter::new(&p);
                let mut measured = 0;
                let found = f
                    .largest(cap, |_, n| {
                        measured += 1;
                        let (slots, executed) = growth(n as u64);
                        Ok(counted(&p, slots, executed))
                    })
                    .unwrap();
                assert_eq!(found, brute, "{name}, cap {cap}");
                if name == "straight" && cap >= 600 {
                    // 1, 2, the guess and the one after it.
                    assert_eq!(measured, 4, "{name}, cap {cap}");
                }
            }
        }
    }

    #[test]
    fn the_widest_unroll_at_512_slots_is_the_articles_125() {
        let p = Profile::ps_3_0();
        let mut f = Fitter::new(&p);
        let n = f.widest(Pass1Form::Unrolled, u32::MAX).unwrap().unwrap();
        assert_eq!(n, 125);
        assert_eq!(
            f.pass1(Pass1Form::Unrolled, 125, 1).unwrap().unwrap().slots,
            511
        );
        assert!(!f
            .pass1(Pass1Form::Unrolled, 126, 1)
            .unwrap()
            .unwrap()
            .fits());
        // 129 lines of 506 plus 6 is 65,280; 130 would be 65,786.
        assert_eq!(
            f.tallest(Pass1Form::Unrolled, 125, 1024).unwrap(),
            Some(129)
        );
        assert_eq!(balanced(1024, 129), 128);
    }

    #[test]
    fn the_loops_tallest_128_wide_block_is_the_articles_56() {
        let p = Profile::ps_3_0();
        let mut f = Fitter::new(&p);
        assert_eq!(f.tallest(Pass1Form::Loop, 128, 1024).unwrap(), Some(56));
        let c = f.pass1(Pass1Form::Loop, 128, 56).unwrap().unwrap();
        assert_eq!((c.slots, c.executed), (20, 64_853));
        // The loop's width is bounded by the rep count, not by slots.
        assert_eq!(f.widest(Pass1Form::Loop, u32::MAX).unwrap(), Some(255));
    }

    #[test]
    fn pass2_falls_back_to_loops_when_unrolling_does_not_fit() {
        let p = Profile::ps_3_0();
        let mut f = Fitter::new(&p);
        let o = f.pass2(11, 8).unwrap();
        assert_eq!(o.choice.as_ref().unwrap().form, Pass2Form::Unrolled);
        assert_eq!(o.choice.unwrap().slots, 190);
        let o = f.pass2(31, 17).unwrap();
        assert_eq!(o.choice.unwrap().form, Pass2Form::RowLoop);
        let o = f.pass2(252, 30).unwrap();
        assert_eq!(o.choice.unwrap().form, Pass2Form::Nested);
        // 300 columns: no rep count covers them, unrolled rows do not fit.
        let o = f.pass2(300, 300).unwrap();
        assert!(o.choice.is_none());
        assert_eq!(o.rejected.len(), 3, "{:?}", o.rejected);
    }

    #[test]
    fn a_nesting_limit_of_one_rules_out_the_loop_form() {
        let p = Profile {
            max_loop_nesting: 1,
            ..Profile::ps_3_0()
        };
        let mut f = Fitter::new(&p);
        assert!(f.pass1(Pass1Form::Loop, 128, 56).unwrap().is_none());
        assert!(f.pass1_unwritable(Pass1Form::Loop, 128, 56).is_some());
        assert_eq!(f.widest(Pass1Form::Unrolled, 4096).unwrap(), Some(125));
    }
}
