//! Fuzz-style property tests of the COLLADA loader: truncated, corrupted
//! and cut-up scene text loads or fails with an error, and never panics.

mod common;

use pathtracer::scene::collada;
use proptest::prelude::*;

use common::MINIMAL;

const FILE: &str = "minimal.dae";

/// The course's `CBspheres.dae`, read once (and said once to be skipped
/// when it is not found).
fn cbspheres_text() -> Option<&'static str> {
    static TEXT: std::sync::OnceLock<Option<String>> = std::sync::OnceLock::new();
    TEXT.get_or_init(|| {
        let path = common::course_file("CBspheres.dae")?;
        Some(std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display())))
    })
    .as_deref()
}

proptest! {
    #![proptest_config(common::cases(512))]

    /// Any prefix of a valid file loads or fails cleanly.
    #[test]
    fn truncation_never_panics(cut in 0..MINIMAL.len()) {
        let _ = collada::load_str(&MINIMAL[..cut], FILE);
    }

    /// Overwriting random bytes with random characters loads or fails cleanly.
    #[test]
    fn corruption_never_panics(
        edits in prop::collection::vec((0..MINIMAL.len(), prop::sample::select(
            b"0123456789 .-e<>/\"#=xNa\n".to_vec())), 1..6)
    ) {
        let mut bytes = MINIMAL.as_bytes().to_vec();
        for (at, byte) in edits {
            bytes[at] = byte;
        }
        let text = String::from_utf8_lossy(&bytes);
        let _ = collada::load_str(&text, FILE);
    }

    /// Any prefix of a course file loads or fails cleanly.
    #[test]
    fn course_file_truncation_never_panics(fraction in 0.0f64..1.0) {
        if let Some(text) = cbspheres_text() {
            let mut cut = (text.len() as f64 * fraction) as usize;
            while !text.is_char_boundary(cut) {
                cut -= 1;
            }
            let _ = collada::load_str(&text[..cut], "CBspheres.dae");
        }
    }

    /// Deleting a random span loads or fails cleanly.
    #[test]
    fn deletion_never_panics(start in 0..MINIMAL.len(), len in 0usize..200) {
        let end = (start + len).min(MINIMAL.len());
        let text = format!("{}{}", &MINIMAL[..start], &MINIMAL[end..]);
        let _ = collada::load_str(&text, FILE);
    }
}
