//! Built-in scenes made in code.
