//! The numeric flags' refusals (issue 25): a negative number after a flag
//! (`-s -1`) is that flag's value, refused with the flag, the rule and the
//! value as typed, never an unknown argument `-1` with a tip that does not
//! work; so is a value too big for the flag's type (`-a 4294967296 0.05`,
//! once echoed as 4294967300) and one that is no number. A flag where a
//! value belongs (`-b -d 2`) is the missing value it is.

use std::process::Command;

use clap::Parser;
use pathtracer::cli::args::BvhArgs;
use pathtracer::cli::CourseArgs;

/// clap's message refusing `args` (the program name is added).
fn refusal(args: &[&str]) -> String {
    let argv = std::iter::once("pathtracer").chain(args.iter().copied());
    match CourseArgs::try_parse_from(argv) {
        Ok(parsed) => panic!("{args:?} accepted: {parsed:?}"),
        Err(e) => e.to_string(),
    }
}

/// Asserts that `args` is refused with "invalid value '<value>' for
/// '<flag>': <rule>".
fn assert_refused(args: &[&str], value: &str, flag: &str, rule: &str) {
    let message = refusal(args);
    let expected = format!("error: invalid value '{value}' for '{flag}': {rule}");
    assert!(
        message.starts_with(&expected),
        "{args:?}:\n{message}\nexpected: {expected}"
    );
    assert!(!message.contains("tip:"), "{args:?}: {message}");
}

const WHOLE_U32_TOO_BIG: &str = "4294967296";
const WHOLE_U64_TOO_BIG: &str = "99999999999999999999";

/// The flags of one value: the flag as clap names it, its rule, and values
/// it refuses: negative, too big, no number.
const SINGLE: [(&str, &str, &str, [&str; 5]); 8] = [
    (
        "-s",
        "-s <N>",
        "must be a whole number from 1 to 1048576",
        ["-1", "1048577", WHOLE_U32_TOO_BIG, WHOLE_U64_TOO_BIG, "x"],
    ),
    (
        "-t",
        "-t <N>",
        "must be a whole number from 1 to 256",
        ["-1", "257", "65536", WHOLE_U64_TOO_BIG, "2.5"],
    ),
    (
        "-l",
        "-l <N>",
        "must be a whole number from 1 to 65536",
        ["-1", "65537", WHOLE_U32_TOO_BIG, WHOLE_U64_TOO_BIG, "four"],
    ),
    (
        "-m",
        "-m <N>",
        "must be a whole number from 0 to 10000",
        ["-1", "10001", WHOLE_U32_TOO_BIG, WHOLE_U64_TOO_BIG, "1e3"],
    ),
    (
        "-o",
        "-o <0|1>",
        "must be 0 or 1",
        ["-1", "2", "256", WHOLE_U64_TOO_BIG, "yes"],
    ),
    (
        "--seed",
        "--seed <SEED>",
        "must be a whole number from 0 to 18446744073709551615",
        [
            "-1",
            "18446744073709551616",
            WHOLE_U64_TOO_BIG,
            "-0.5",
            "0x10",
        ],
    ),
    (
        "-b",
        "-b <RADIUS>",
        "must be a number from 0 to 3.4028235e38",
        ["-1", "-0.05", "1e39", "-.5", "nan"],
    ),
    (
        "-d",
        "-d <DISTANCE>",
        "must be a number greater than 0, at most 3.4028235e38",
        ["-1", "0", "1e39", "-1e-5", "inf"],
    ),
];

#[test]
fn each_single_valued_flag_refuses_with_the_flag_the_rule_and_the_value_as_typed() {
    for (flag, name, rule, values) in SINGLE {
        for value in values {
            assert_refused(&[flag, value], value, name, rule);
            // The same with the value attached, and after a scene file.
            if flag.starts_with("--") {
                assert_refused(&[&format!("{flag}={value}")], value, name, rule);
            }
            assert_refused(&["s.dae", flag, value, "--info"], value, name, rule);
        }
    }
}

#[test]
fn the_two_valued_flags_refuse_either_value() {
    let size = "must be a whole number from 1 to 16384";
    let pixel = "must be a whole number from 0 to 4294967295";
    let batch = "BATCH must be a whole number from 1 to 1000000";
    let tolerance = "TOL must be a number greater than 0, at most 3.4028235e38";
    for value in ["-1", "16385", WHOLE_U32_TOO_BIG, WHOLE_U64_TOO_BIG, "x"] {
        assert_refused(&["-r", value, "480"], value, "-r <WIDTH> <HEIGHT>", size);
        assert_refused(&["-r", "640", value], value, "-r <WIDTH> <HEIGHT>", size);
    }
    for value in ["-1", WHOLE_U32_TOO_BIG, WHOLE_U64_TOO_BIG, "1.5"] {
        assert_refused(
            &["--focus-at", value, "3"],
            value,
            "--focus-at <X> <Y>",
            pixel,
        );
        assert_refused(
            &["--focus-at", "3", value],
            value,
            "--focus-at <X> <Y>",
            pixel,
        );
    }
    for value in ["-1", "0", "1000001", WHOLE_U32_TOO_BIG, "2.5", "x"] {
        assert_refused(&["-a", value, "0.05"], value, "-a <BATCH> <TOL>", batch);
    }
    for value in ["-1", "-0.05", "0", "1e39", "nan", "x"] {
        assert_refused(&["-a", "32", value], value, "-a <BATCH> <TOL>", tolerance);
    }
    // A second -a is BATCH then TOL again, and the last one counts.
    assert_refused(
        &["-a", "32", "0.05", "-a", "-2", "0.05"],
        "-2",
        "-a <BATCH> <TOL>",
        batch,
    );
    let last = CourseArgs::try_parse_from(["p", "-a", "32", "0.05", "-a", "64", "0.1"]).unwrap();
    assert_eq!(last.adaptive, Some(vec![64.0, 0.1]));
}

#[test]
fn a_value_that_rounds_to_zero_says_so() {
    let message = refusal(&["-d", "1e-50"]);
    assert!(
        message.contains("'1e-50'") && message.contains("is 0 as a 32-bit float"),
        "{message}"
    );
}

#[test]
fn values_in_range_are_accepted_at_both_ends() {
    let a = CourseArgs::try_parse_from([
        "p",
        "-s",
        "1048576",
        "-t",
        "256",
        "-l",
        "65536",
        "-m",
        "0",
        "-o",
        "0",
        "--seed",
        "18446744073709551615",
        "-b",
        "-0",
        "-d",
        "1e-40",
        "-r",
        "16384",
        "1",
        "-a",
        "1000000",
        "1e-3",
        "--focus-at",
        "0",
        "4294967295",
    ])
    .unwrap();
    assert_eq!(
        (a.samples, a.threads, a.light_samples, a.max_depth),
        (Some(1 << 20), Some(256), Some(1 << 16), Some(0))
    );
    assert_eq!((a.accumulate, a.seed), (0, u64::MAX));
    assert_eq!(a.lens_radius.to_bits(), 0.0f32.to_bits(), "-0 is 0");
    assert!(a.focal_distance > 0.0);
    assert_eq!(a.resolution, Some(vec![16384, 1]));
    assert_eq!(a.adaptive, Some(vec![1e6, 1e-3]));
    assert_eq!(a.focus_at, Some(vec![0, u32::MAX]));
}

/// A flag where the value belongs is a missing value, not the value, and
/// the flag after it is not swallowed into an accepted command line.
#[test]
fn a_flag_after_a_numeric_flag_is_its_missing_value() {
    for (args, name) in [
        (&["-b", "-d", "2"][..], "-b <RADIUS>"),
        (&["-s", "--info"], "-s <N>"),
        (&["-d", "-H"], "-d <DISTANCE>"),
        (&["--seed", "--course"], "--seed <SEED>"),
        (&["-r", "640", "-s", "4"], "-r <WIDTH> <HEIGHT>"),
        (&["-a", "32", "-H"], "-a <BATCH> <TOL>"),
        (&["-m", "--"], "-m <N>"),
    ] {
        let message = refusal(args);
        assert!(
            message.starts_with(&format!(
                "error: a value is required for '{name}' but none was supplied"
            )),
            "{args:?}: {message}"
        );
    }
}

#[test]
fn part2_bvh_refuses_the_same_way() {
    let message = BvhArgs::try_parse_from(["part2-bvh", "--bench", "-s", "-1"])
        .unwrap_err()
        .to_string();
    assert!(
        message.starts_with(
            "error: invalid value '-1' for '-s <N>': must be a whole number from 1 to 1048576"
        ),
        "{message}"
    );
}

/// What a user sees: the message on stderr, a failure status, no tip.
#[test]
fn the_binaries_print_the_refusal() {
    for (binary, args, expected) in [
        (
            env!("CARGO_BIN_EXE_pathtracer"),
            &["-s", "-1"][..],
            "error: invalid value '-1' for '-s <N>': must be a whole number from 1 to 1048576\n",
        ),
        (
            env!("CARGO_BIN_EXE_pathtracer"),
            &["-a", "4294967296", "0.05"],
            "error: invalid value '4294967296' for '-a <BATCH> <TOL>': \
             BATCH must be a whole number from 1 to 1000000\n",
        ),
        (
            env!("CARGO_BIN_EXE_part8-dof"),
            &["-b", "-1", "-d", "4"],
            "error: invalid value '-1' for '-b <RADIUS>': must be a number from 0 to 3.4028235e38\n",
        ),
        (
            env!("CARGO_BIN_EXE_part2-bvh"),
            &["--seed", "-1"],
            "error: invalid value '-1' for '--seed <SEED>': \
             must be a whole number from 0 to 18446744073709551615\n",
        ),
        (
            env!("CARGO_BIN_EXE_check"),
            &["--student", "x", "-t", "-1"],
            "error: invalid value '-1' for '--threads <THREADS>': \
             must be a whole number from 1 to 256\n",
        ),
        (
            env!("CARGO_BIN_EXE_check"),
            &["--student", "x", "--timeout", "-5"],
            "error: invalid value '-5' for '--timeout <TIMEOUT>': \
             must be a whole number from 1 to 86400\n",
        ),
        (
            env!("CARGO_BIN_EXE_check"),
            &["--student", "x", "--part", "-1"],
            "error: invalid value '-1' for '--part <PARTS>': must be a whole number from 1 to 8\n",
        ),
    ] {
        let out = Command::new(binary).args(args).output().expect("binary runs");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?}");
        assert!(stderr.starts_with(expected), "{args:?}: {stderr}");
        assert!(!stderr.contains("tip:") && !stderr.contains("4294967300"), "{stderr}");
    }
}
