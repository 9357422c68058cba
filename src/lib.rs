//! ps30
pub mod ir;
pub mod isa;
pub mod image;
pub mod reference;
pub mod emu;
