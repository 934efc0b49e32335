//! `report.html`: one self-contained page (every image inlined as a PNG
//! data URI; no server, no network), readable offline. For each check: the
//! verdict, what differs, the student's image beside the reference and
//! the ratio of the two as a heat map with its colour bar (and for a
//! check with `-a` the same three of the sample-rate images), and the
//! named mistakes with their images at the same flags. The markup is well-formed
//! XML too, so a test can read it without a browser.

use std::fmt::Write as _;
use std::io::{self, Cursor};
use std::path::{Path, PathBuf};

use super::battery::SIZE;
use super::probe::report::{anchor, probe_of};
use super::probe::ProbeResult;
use super::scan::WINDOW;
use super::stats::{block_index, BLOCK};
use super::verdict::{CheckImages, CheckResult, Outcome};
use crate::math::ratio_colour;

/// Standard base64 (RFC 4648) of `bytes`.
pub fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut text = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            *chunk.get(1).unwrap_or(&0),
            *chunk.get(2).unwrap_or(&0),
        ];
        let n = (b[0] as u32) << 16 | (b[1] as u32) << 8 | b[2] as u32;
        for k in 0..4 {
            if k <= chunk.len() {
                text.push(ALPHABET[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                text.push('=');
            }
        }
    }
    text
}

/// An 8-bit RGB image as a PNG data URI.
pub(crate) fn data_uri(width: u32, height: u32, rgb: &[u8]) -> String {
    let mut png = Vec::new();
    let encoded = image::RgbImage::from_raw(width, height, rgb.to_vec())
        .map(|im| im.write_to(&mut Cursor::new(&mut png), image::ImageFormat::Png));
    match encoded {
        Some(Ok(())) => format!("data:image/png;base64,{}", base64(&png)),
        _ => String::new(),
    }
}

/// The ratio map: each block coloured by `log2(ratio)` from 1/4 (blue)
/// to 4 (red), and a colour bar of 12 rows under it.
fn ratio_map(ratio: &[f64]) -> (u32, u32, Vec<u8>) {
    let (w, h) = (SIZE.0, SIZE.1 + 12);
    let mut rgb = Vec::with_capacity((w * h * 3) as usize);
    for y in 0..h {
        for x in 0..w {
            let t = if y >= SIZE.1 {
                2.0 * x as f32 / (w - 1) as f32 - 1.0
            } else {
                let r = ratio[block_index(x, y, SIZE.0)];
                (r.max(1e-6).log2() / 2.0) as f32
            };
            rgb.extend(
                ratio_colour(t)
                    .to_array()
                    .map(|c| (255.0 * c).round() as u8),
            );
        }
    }
    (w, h, rgb)
}

/// `text` with `&`, `<` and `>` escaped for HTML.
pub(crate) fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// How wide each picture is shown: three to a row.
const SHOWN_WIDTH: u32 = 300;

fn figure(caption: &str, width: u32, height: u32, rgb: &[u8]) -> String {
    format!(
        r#"<figure><img alt="{c}" width="{SHOWN_WIDTH}" src="{}"/><figcaption>{c}</figcaption></figure>"#,
        data_uri(width, height, rgb),
        c = escape(caption)
    )
}

/// The catalogue's pages of symptoms in this project's docs, where the
/// report links each named mistake (its section's anchor is its name).
pub(crate) const SYMPTOMS: &str = concat!(
    "file://",
    env!("CARGO_MANIFEST_DIR"),
    "/docs/13-symptoms.md"
);

fn section(i: usize, r: &CheckResult, probes: &[ProbeResult]) -> String {
    let c = &r.check;
    let run = if r.command.is_empty() {
        format!("Flags: <code>{}</code>.", escape(&c.flags(2).join(" ")))
    } else {
        format!(
            "Run (in <code>runs/</code>, to reproduce it): <code>{}</code>.",
            escape(&r.command.join(" "))
        )
    };
    let mut html = format!(
        r#"<section id="check-{i}"><h2>Part {}: {} <span class="{v}">{v}</span></h2><p>Starter function: <code>{}</code> in <code>{}</code>. {run}</p>"#,
        c.part,
        escape(c.name),
        c.function,
        c.file,
        v = r.outcome.word()
    );
    match &r.outcome {
        Outcome::Pass {
            statistic,
            threshold,
            region,
            region_threshold,
            variant,
        } => {
            let whose = match variant {
                Some(chose) => format!("a correct solution that {chose}"),
                None => "a correct solution".into(),
            };
            let _ = write!(
                html,
                "<p>Within the noise of {whose}. {}</p>",
                test_values(*statistic, *threshold, *region, *region_threshold)
            );
        }
        Outcome::Fail {
            statistic,
            threshold,
            region,
            region_threshold,
            what,
            ..
        } => {
            let _ = write!(
                html,
                "<p>{}. {}</p>",
                escape(what),
                test_values(*statistic, *threshold, *region, *region_threshold)
            );
            let pointed = std::iter::once(c.function)
                .chain(r.outcome.likely_mistake().map(|m| m.info().function));
            if let Some(k) = pointed.filter_map(|f| probe_of(probes, f)).next() {
                let _ = write!(
                    html,
                    r##"<p>The probe of <a href="#{}"><code>{}</code></a> tests that function alone: {}.</p>"##,
                    anchor(k),
                    escape(probes[k].probe.function),
                    probes[k].verdict.word()
                );
            }
        }
        Outcome::Skipped(why) | Outcome::Error(why) => {
            let _ = write!(html, "<p>{}</p>", escape(why));
        }
        Outcome::NotWritten(u) => {
            let _ = write!(
                html,
                "<p>Not written yet: <code>{}</code> in <code>{}</code> (part {}): {}.</p>",
                escape(u.function),
                escape(u.file),
                u.part,
                escape(u.shows)
            );
        }
    }
    if let Some(images) = &r.images {
        html += &figures(images);
    }
    if let Outcome::Fail { suspects, .. } = &r.outcome {
        html += "<h3>Likely mistakes</h3><ol>";
        for s in suspects.iter().take(super::verdict::SHOWN_SUSPECTS) {
            let info = s.mistake.info();
            let fit = if s.fits { "fits" } else { "does not fit" };
            let _ = write!(
                html,
                r#"<li><b><a href="{SYMPTOMS}#{}">{}</a></b> ({fit}; misfit {:.2} per cell). Look at <code>{}</code>: {}. Shows: {}."#,
                info.name,
                info.name,
                s.misfit,
                escape(info.function),
                escape(info.what),
                escape(info.symptom)
            );
            let image = r
                .images
                .as_ref()
                .and_then(|im| im.suspects.iter().find(|(m, _)| *m == s.mistake));
            if let Some((_, rgb)) = image {
                html += &figure(&format!("--mistake {}", info.name), SIZE.0, SIZE.1, rgb);
            }
            html += "</li>";
        }
        html += "</ol>";
    }
    html + "</section>\n"
}

/// The image's two tests, each value against its threshold: the sum over
/// every cell ([`crate::check::stats::statistic`]) and the region test's
/// most different window ([`crate::check::scan`]).
fn test_values(statistic: f64, threshold: f64, region: f64, region_threshold: f64) -> String {
    let side = WINDOW * BLOCK;
    format!(
        "The image as a whole: {statistic:.1} (threshold {threshold:.1}); its most different {side} x {side} region: {region:.1} (threshold {region_threshold:.1})."
    )
}

fn figures(images: &CheckImages) -> String {
    let (w, h, ratio) = ratio_map(&images.ratio);
    let rates = images.rates.as_ref().map_or(String::new(), |r| {
        let (w, h, ratio) = ratio_map(&r.ratio);
        format!(
            r#"<p>The sample-rate images (blue: few of the samples, green: half, red: all): yours took {:.1} % of the samples on average, a correct solution's {:.1} %. Statistic {:.1}, threshold {:.1}.</p><div class="row">{}{}{}</div>"#,
            100.0 * r.student_mean,
            100.0 * r.reference_mean,
            r.statistic,
            r.threshold,
            figure("your rate image", SIZE.0, SIZE.1, &r.student),
            figure(
                "a correct solution's (mean of 8 renders' rates)",
                SIZE.0,
                SIZE.1,
                &r.reference
            ),
            figure(
                "your rates / correct: blue 1/4, white 1, red 4",
                w,
                h,
                &ratio
            )
        )
    });
    format!(
        r#"<div class="row">{}{}{}</div>{rates}"#,
        figure("your image", SIZE.0, SIZE.1, &images.student),
        figure(
            "a correct solution's (mean of 8 renders)",
            SIZE.0,
            SIZE.1,
            &images.reference
        ),
        figure(
            "yours / correct, radiance: blue 1/4, white 1, red 4",
            w,
            h,
            &ratio
        )
    )
}

/// The page for `results` of the binary `student` on `scene`.
pub fn html(student: &str, scene: &str, results: &[CheckResult]) -> String {
    page(Some((student, scene, results)), None)
}

/// The functions probed in a tree ([`crate::check::probe`]): the tree,
/// the results, and the folder of the probe's runs (its pictures).
pub type Functions<'a> = (&'a str, &'a [ProbeResult], &'a Path);

/// The page: the functions of `--source` when probed, then the images of
/// `--student` (the binary, the scene, the checks) when checked; a failed
/// check links to the probe of its function.
pub fn page(images: Option<(&str, &str, &[CheckResult])>, functions: Option<Functions>) -> String {
    let mut page = String::from(
        r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"/><title>check: your renderer against the course's</title>
<style>body{font-family:sans-serif;max-width:60em;margin:auto}img{image-rendering:pixelated}
figure{display:inline-block;margin:0.3em;width:300px;vertical-align:top}.FAIL,.error{color:#b00}.pass{color:#070}.skipped{color:#777}
table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:0.2em 0.5em}</style></head><body>
"#,
    );
    let probes = functions.map_or(&[][..], |(_, results, _)| results);
    if let Some((source, results, runs)) = functions {
        page += &super::probe::report::section(source, results, runs);
    }
    let Some((student, scene, results)) = images else {
        return page + "</body></html>\n";
    };
    page += "<h1>Your renderer against the course's image</h1>\n";
    let _ = write!(
        page,
        "<p>Binary <code>{}</code>, scene <code>{}</code>. Each check compares your image with the distribution of a correct course solution's images at the same flags (docs/15-check.md).</p>\n<table><tr><th>part</th><th>check</th><th>verdict</th><th>likely mistake</th></tr>",
        escape(student),
        escape(scene)
    );
    for (i, r) in results.iter().enumerate() {
        let likely = match (&r.outcome, r.outcome.likely_mistake()) {
            (_, Some(_)) => r.outcome.likely_mistake_named().unwrap_or_default(),
            (Outcome::Fail { .. }, None) => "none known fits".to_string(),
            (Outcome::NotWritten(u), None) => format!("not written yet: {}", escape(u.function)),
            _ => String::new(),
        };
        let v = r.outcome.word();
        let _ = write!(
            page,
            r##"<tr><td>{}</td><td><a href="#check-{i}">{}</a></td><td class="{v}">{v}</td><td>{likely}</td></tr>"##,
            r.check.part,
            escape(r.check.name)
        );
    }
    page += "</table>\n";
    for (i, r) in results.iter().enumerate() {
        page += &section(i, r, probes);
    }
    page + "</body></html>\n"
}

/// Writes the page to `out/report.html`, whole or not at all (a temporary
/// file renamed into place).
pub fn write_report(out: &Path, page: &str) -> io::Result<PathBuf> {
    let path = out.join("report.html");
    let partial = out.join(".report.html.partial");
    std::fs::write(&partial, page)?;
    std::fs::rename(&partial, &path)?;
    Ok(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc_4648() {
        // RFC 4648, section 10.
        let cases = [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ];
        for (plain, encoded) in cases {
            assert_eq!(base64(plain.as_bytes()), encoded);
        }
    }
}
