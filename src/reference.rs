//! CPU reference (placeholder).
