//! `--info`: a one-item-per-line summary of a loaded scene.
