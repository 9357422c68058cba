//! Scenes: synthetic inputs with a CPU computation to check a shader
//! against, for shaders that do not read an HDR photograph.

pub mod lights;
