//! The functions' part of `report.html`: a table of every probed function
//! and its verdict, then a section each: the verdict, the first failing
//! input with what was expected and what came back, the catalogued
//! mistake it is (linked to its symptoms), the function it waits on, and
//! for a sampler the warptest picture ([`super::picture`]).

use std::fmt::Write as _;
use std::path::Path;

use super::picture;
use super::{ProbeResult, Verdict};
use crate::check::report::{data_uri, escape, SYMPTOMS};

/// The anchor of the section of result `i`.
pub fn anchor(i: usize) -> String {
    format!("fn-{i}")
}

/// The index of the result that probed the function named in `text`
/// (`"Triangle::intersect / Sphere::intersect"` names two), the first
/// that did not pass preferred.
pub fn probe_of(results: &[ProbeResult], text: &str) -> Option<usize> {
    let named = |r: &&ProbeResult| text.contains(r.probe.function);
    let failing = results
        .iter()
        .position(|r| named(&r) && !r.verdict.is_pass());
    failing.or_else(|| results.iter().position(|r| named(&r)))
}

/// The HTML of the functions of the tree `source`, the pictures read from
/// `runs`.
pub fn section(source: &str, results: &[ProbeResult], runs: &Path) -> String {
    let mut html = format!(
        r#"<h1 id="functions">Your functions, one by one</h1><p>Tree <code>{}</code>: each function compiled with this project's probe and run on many inputs, each answer held to the exact one (docs/15-check.md).</p><table><tr><th>part</th><th>function</th><th>verdict</th><th>likely mistake</th></tr>"#,
        escape(source)
    );
    for (i, r) in results.iter().enumerate() {
        let word = r.verdict.word();
        let likely = match &r.verdict {
            Verdict::Fail(f) => f.mistake.map_or_else(String::new, |m| {
                format!(r#"<a href="{SYMPTOMS}#{m}">{m}</a>"#)
            }),
            _ => String::new(),
        };
        let _ = write!(
            html,
            r##"<tr><td>{}</td><td><a href="#{}">{}</a></td><td class="{}">{word}</td><td>{likely}</td></tr>"##,
            r.probe.part,
            anchor(i),
            escape(r.probe.function),
            class(&r.verdict)
        );
    }
    html += "</table>\n";
    for (i, r) in results.iter().enumerate() {
        html += &one(i, r, runs);
    }
    html
}

/// The style class of a verdict (the page's colours).
fn class(v: &Verdict) -> &'static str {
    match v {
        Verdict::Pass { .. } => "pass",
        Verdict::Fail(_) | Verdict::Broken(_) => "FAIL",
        Verdict::NotWritten(_) | Verdict::Waits(_) => "skipped",
    }
}

fn one(i: usize, r: &ProbeResult, runs: &Path) -> String {
    let mut html = format!(
        r#"<section id="{}"><h2>Part {}: <code>{}</code> <span class="{}">{}</span></h2><p>In <code>{}</code>.</p>"#,
        anchor(i),
        r.probe.part,
        escape(r.probe.function),
        class(&r.verdict),
        r.verdict.word(),
        r.probe.file
    );
    match &r.verdict {
        Verdict::Fail(f) => {
            let _ = write!(
                html,
                "<p>{} ({} of {} cases fail; the first:)</p><table><tr><th>input</th><td>{}</td></tr><tr><th>expected</th><td>{}</td></tr><tr><th>yours</th><td>{}</td></tr></table>",
                escape(&f.what),
                f.failed,
                f.cases,
                escape(&f.input),
                escape(&f.expected),
                escape(&f.got)
            );
            if let Some(m) = f.mistake {
                let info = m.info();
                let _ = write!(
                    html,
                    r#"<p>This is <b><a href="{SYMPTOMS}#{m}">{m}</a></b>: {}. In a render it shows as: {}. <code>pathtracer --mistake {m}</code> renders it.</p>"#,
                    escape(info.what),
                    escape(info.symptom)
                );
            }
        }
        other => {
            let _ = write!(html, "<p>{}</p>", escape(&other.to_string()));
        }
    }
    if let Some(need) = r.blocked_by {
        let _ = write!(
            html,
            "<p>It calls <code>{}</code>, which does not pass: fix that first.</p>",
            escape(need)
        );
    }
    let file = picture::file_name(runs, r.probe.function);
    if let Ok(image) = image::open(&file) {
        let rgb = image.to_rgb8();
        let _ = write!(
            html,
            r#"<figure style="width:auto"><img alt="warptest" src="{}"/><figcaption>Your samples: your histogram, the counts the pdfs you return expect, and their difference in standard errors (blue -4, white 0, red +4); a BSDF's over the hemisphere (cos theta down from 1, phi across), the environment light's over the map's texels.</figcaption></figure>"#,
            data_uri(rgb.width(), rgb.height(), rgb.as_raw())
        );
    }
    html + "</section>\n"
}
