//! The font the examples' charts and labelled grids draw text with:
//! DejaVu Sans from the `dejavu` crate, registered once with plotters as
//! "sans-serif", so no system font or fontconfig is needed.

use std::error::Error;
use std::sync::Once;

use plotters::style::FontStyle;

/// Registers DejaVu Sans as plotters' "sans-serif" (once per process).
pub fn register_font() -> Result<(), Box<dyn Error>> {
    static ONCE: Once = Once::new();
    let mut result = Ok(());
    ONCE.call_once(|| {
        result = plotters::style::register_font(
            "sans-serif",
            FontStyle::Normal,
            dejavu::sans::regular(),
        )
        .map_err(|_| "DejaVu Sans did not load".into());
    });
    result
}
