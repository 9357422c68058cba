//! The front end: assembly text → statements with spans → expanded
//! statements, and back to text.
//!
//! [`parse`](parse::parse) runs the [`preprocess`]or when a file has
//! directives and reads lines into an AST with spans,
//! [`repeat::expand`] unrolls REPEAT_BLOCK macros, and [`print`](mod@print) writes a
//! validated program back as plain assembly. Lowering and checking the AST
//! is the next stage ([`crate::core::valid`]); [`crate::core::load`] runs
//! them all.

pub mod ast;
pub mod parse;
pub mod preprocess;
pub mod print;
pub mod repeat;
