//! Studies: the alternatives to the article's methods that were used on the
//! same hardware, each run in the emulator as a draw list
//! ([`crate::jobs::render`]) and measured against the f64 truth, and the
//! article's own lighting-to-display chain end to end.
//!
//! * [`mip_luminance`] — log-luminance encoded into 8-bit destination alpha
//!   and averaged by the mip chain, against the article's two passes;
//! * [`log_lights`] — lights stored as exp2(−light) and multiplied into an
//!   RGBA8 buffer, against raw RGBA8 and A16B16G16R16F accumulation;
//! * [`article_chain`] — several lights of the light-model shader added into
//!   A16B16G16R16F, L̄w by the luminance passes, tone-mapped to 8-bit sRGB.
//!
//! Each returns plain data; `crate::present::study` prints it and writes
//! its report page.

pub mod article_chain;
pub mod log_lights;
pub mod mip_luminance;
