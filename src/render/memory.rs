//! The memory an image needs, checked before a render starts, so that a
//! legal but huge resolution (`-r 16384 16384`) is refused with the
//! figures instead of aborting on a failed allocation after minutes.
//!
//! A render holds, per pixel, its estimate (mean radiance, sample counts
//! and variance: 32 bytes) while it runs and then the film (12 bytes),
//! the display values (12 bytes) and the encoded bytes of the image and of
//! the rate image. `/usr/bin/time` measured 64 bytes a pixel of peak
//! memory at 4096 x 4096 against 1024 x 1024 (`pathtracer -r N N -s 1
//! -m 0 -f big.png`); [`BYTES_PER_PIXEL`] adds half of that as a margin
//! for the allocator and the encoders. The scene and its BVH come on top.

/// The memory a render is taken to need per pixel.
pub const BYTES_PER_PIXEL: u64 = 96;

/// The bytes a `width` x `height` render is taken to need.
pub fn image_bytes(width: u32, height: u32) -> u64 {
    width as u64 * height as u64 * BYTES_PER_PIXEL
}

/// The memory the system says is available to a new allocation
/// (`MemAvailable` of `/proc/meminfo`), or `None` where that cannot be read.
pub fn available_bytes() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    parse_mem_available(&text)
}

/// `MemAvailable:   123456 kB` in `/proc/meminfo`'s text, in bytes.
fn parse_mem_available(meminfo: &str) -> Option<u64> {
    let line = meminfo.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

/// Refuses a `width` x `height` render that needs more memory than
/// `available` (bytes; `None`: unknown, nothing refused), saying both.
pub fn check_image_memory(width: u32, height: u32, available: Option<u64>) -> Result<(), String> {
    shortfall(image_bytes(width, height) as u128, available).map_or(Ok(()), |words| {
        Err(format!(
            "a {width} x {height} image {words} ({BYTES_PER_PIXEL} bytes a pixel); \
             choose a smaller resolution (-r)"
        ))
    })
}

/// When `needed` bytes do not fit in `available` (`None`: unknown, so
/// they are taken to fit), both in words: "needs about 25.8 GB of memory
/// and 22.0 GB is available".
pub fn shortfall(needed: u128, available: Option<u64>) -> Option<String> {
    let available = available.filter(|&a| needed > a as u128)?;
    Some(format!(
        "needs about {} of memory and {} is available",
        amount(needed),
        amount(available as u128)
    ))
}

/// `bytes` in the largest unit that keeps a number of at least 1, with
/// one decimal: `25.8 GB`, `512 bytes`.
pub fn amount(bytes: u128) -> String {
    let units = ["bytes", "kB", "MB", "GB", "TB", "PB", "EB", "ZB", "YB"];
    let mut value = bytes as f64;
    let mut unit = 0;
    while value >= 1000.0 && unit + 1 < units.len() {
        value /= 1000.0;
        unit += 1;
    }
    if unit == 0 {
        format!("{bytes} bytes")
    } else {
        format!("{value:.1} {}", units[unit])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_render_too_big_for_memory_is_refused_with_both_figures() {
        let e = check_image_memory(16384, 16384, Some(22_000_000_000)).unwrap_err();
        assert!(e.contains("25.8 GB") && e.contains("22.0 GB"), "{e}");
        assert!(check_image_memory(480, 360, Some(1_000_000_000)).is_ok());
        assert!(check_image_memory(16384, 16384, None).is_ok());
    }

    #[test]
    fn mem_available_is_read_from_meminfo() {
        let text = "MemTotal:       24000000 kB\nMemAvailable:   22000000 kB\n";
        assert_eq!(
            parse_mem_available(text),
            Some(22_000_000_000 * 1024 / 1000)
        );
        assert_eq!(parse_mem_available("MemTotal: 1 kB\n"), None);
    }
}
