//! Mutation of the command line's values: each flag with numbers of every
//! kind (negative, zero, too big for its type, not finite, not numbers),
//! alone or with others. Whatever is refused must quote the value as
//! typed; whatever is accepted must render.

use rand::seq::SliceRandom;
use rand::Rng;

/// The numeric flags and how many values each takes.
const FLAGS: [(&str, usize); 11] = [
    ("-s", 1),
    ("-l", 1),
    ("-m", 1),
    ("-t", 1),
    ("-o", 1),
    ("-b", 1),
    ("-d", 1),
    ("--seed", 1),
    ("-r", 2),
    ("-a", 2),
    ("--focus-at", 2),
];

/// Values of every kind, small enough where legal that a render is quick.
const VALUES: [&str; 22] = [
    "-1",
    "0",
    "1",
    "2",
    "3",
    "-0",
    "0.5",
    "-0.5",
    "1e20",
    "1e-50",
    "3.4e38",
    "4294967296",
    "99999999999999999999",
    "nan",
    "inf",
    "-inf",
    "abc",
    "",
    "0x10",
    "1,5",
    "+2",
    "-2147483649",
];

/// A command line's fuzzed flags (the rest come from the small render).
pub struct FlagMutant {
    pub flags: Vec<String>,
    pub what: String,
}

/// One to three flags with values chosen by `rng`.
pub fn mutate(rng: &mut impl Rng) -> FlagMutant {
    let mut flags = Vec::new();
    let mut chosen: Vec<&str> = Vec::new();
    for _ in 0..rng.gen_range(1..=3) {
        let (flag, count) = *FLAGS.choose(rng).unwrap();
        if chosen.contains(&flag) {
            continue;
        }
        chosen.push(flag);
        flags.push(flag.to_string());
        for _ in 0..count {
            flags.push(VALUES.choose(rng).unwrap().to_string());
        }
    }
    FlagMutant {
        what: flags.join(" "),
        flags,
    }
}

/// Whether a refusal quotes one of `flags`' values as typed: clap's
/// "invalid value 'X'" must name an X that was typed.
pub fn quotes_as_typed(message: &str, flags: &[String]) -> bool {
    let Some(start) = message.find("invalid value '") else {
        return true;
    };
    let rest = &message[start + "invalid value '".len()..];
    let Some(end) = rest.find('\'') else {
        return false;
    };
    flags.iter().any(|f| f == &rest[..end])
}
