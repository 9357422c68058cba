//! Images in and out (placeholder).
