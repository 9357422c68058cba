//! Presentation: the text, JSON, Markdown pages and figures in which results
//! reach a person. Nothing here computes a result; every function takes what
//! a job or a core stage returned and renders it.

pub mod check;
pub mod compare;
pub mod constants;
pub mod corpus;
pub mod decompile;
pub mod disasm;
pub mod history;
pub mod json;
pub mod luminance;
pub mod plan;
pub mod profile;
pub mod render;
pub mod report;
pub mod shader_test;
pub mod shaders;
pub mod study;
pub mod tonemap;
pub mod unroll;
pub mod verify;
pub mod vertices;
