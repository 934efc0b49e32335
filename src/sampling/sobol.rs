//! The first two dimensions of the Sobol' sequence, and Owen scrambling by
//! hashing.
//!
//! Sobol' point `i` in dimension `d` (Sobol' 1967): write
//! `i = sum_j a_j 2^j` in base 2 and multiply the digit vector by the
//! dimension's generator matrix over GF(2),
//!
//! ```text
//! x = sum_j a_j C_d[:, j]   (XOR of the columns j with a_j = 1),
//! value = sum_k x_k 2^-k    (row k of C_d is the k-th binary digit)
//! ```
//!
//! - Dimension 0: `C_0` is the identity, so `x` is `i`'s bits reversed:
//!   the van der Corput radical inverse in base 2.
//! - Dimension 1: the primitive polynomial `x + 1` with direction numbers
//!   `m_k = 1` gives Pascal's triangle mod 2, `C_1[k][j] = binom(j, k) mod 2`.
//!   Column `j` as a 32-bit word (row 0 the most significant bit) obeys
//!   `c_0 = 2^31`, `c_j = c_{j-1} xor (c_{j-1} >> 1)`, Pascal's rule
//!   `binom(j, k) = binom(j-1, k) + binom(j-1, k-1)`.
//!
//! The two dimensions together are a (0, 2)-sequence in base 2
//! (Niederreiter 1992, section 4.5): every aligned block of `2^m`
//! consecutive points, `i in [q 2^m, (q + 1) 2^m)`, is a (0, m, 2)-net:
//! each elementary interval `[a 2^-p, (a + 1) 2^-p) x [b 2^-(m-p), (b + 1) 2^-(m-p))`
//! holds exactly one point.
//!
//! Owen scrambling (Owen 1995) permutes the digits of every value at
//! random, digit `k` flipped by a random bit that depends on digits
//! `1..k-1` only (a nested uniform scramble): each scrambled point is
//! uniform on `[0, 1)`, and nets stay nets. Burley (2020), "Practical
//! Hash-based Owen Scrambling", JCGT 9(4), section 3, does it with a hash:
//! reverse the bits, so a value's leading digits are the low bits, apply
//! the Laine-Karras permutation with a seed,
//!
//! ```text
//! x += seed; x ^= x * 0x6c50b47c; x ^= x * 0xb82f1e52;
//! x ^= x * 0xc7afe638; x ^= x * 0x8d22f6e6      (wrapping, 32 bits)
//! ```
//!
//! and reverse back. An addition changes bit `k` by a carry from the bits
//! below it, and `x * c` with `c` even has bit `k` a function of the bits
//! below `k`: every step is nested, hence the net property is kept.
//!
//! The samples are computed with their bits reversed until the end: in
//! dimension 0 the reversed van der Corput value is the index itself, and
//! in dimension 1 the tables hold Pascal's columns reversed, so each value
//! costs one bit reversal.

/// The scrambled Sobol' sample of `index` in dimension `dimension` (0 or
/// 1), as 32 binary digits, scrambled with `seed`: `owen_scramble` of
/// [`van_der_corput`] or [`pascal`], computed on the reversed bits.
#[inline]
pub fn scrambled_sobol(index: u64, dimension: u32, seed: u32) -> u32 {
    let reversed = match dimension {
        0 => index as u32,
        _ => pascal_reversed(index),
    };
    laine_karras(reversed, seed).reverse_bits()
}

/// Dimension 0: the digits of `index` (its low 32 bits) in reverse order.
#[inline]
pub fn van_der_corput(index: u64) -> u32 {
    (index as u32).reverse_bits()
}

/// Dimension 1: `index`'s digits times Pascal's matrix mod 2.
#[inline]
pub fn pascal(index: u64) -> u32 {
    pascal_reversed(index).reverse_bits()
}

/// [`pascal`] with its bits reversed, a byte of the index at a time (the
/// XOR of the reversed columns of each byte's set bits is tabled; the
/// eight look-ups are independent of each other).
#[inline]
fn pascal_reversed(index: u64) -> u32 {
    let bytes = index.to_le_bytes();
    let mut x = 0;
    for (table, &byte) in PASCAL_BYTES.iter().zip(&bytes) {
        x ^= table[byte as usize];
    }
    x
}

/// `PASCAL_BYTES[k][v]`: the XOR of the columns `8k + b` of Pascal's
/// matrix for the set bits `b` of `v`, bits reversed.
static PASCAL_BYTES: [[u32; 256]; 8] = pascal_tables();

const fn pascal_tables() -> [[u32; 256]; 8] {
    let mut columns = [0u32; 64];
    let mut column = 1u32 << 31;
    let mut j = 0;
    while j < 64 {
        columns[j] = column;
        column ^= column >> 1;
        j += 1;
    }
    let mut tables = [[0u32; 256]; 8];
    let mut k = 0;
    while k < 8 {
        let mut v = 0;
        while v < 256 {
            let (mut x, mut b) = (0, 0);
            while b < 8 {
                if (v >> b) & 1 == 1 {
                    x ^= columns[8 * k + b].reverse_bits();
                }
                b += 1;
            }
            tables[k][v] = x;
            v += 1;
        }
        k += 1;
    }
    tables
}

/// Burley's nested uniform scramble of the binary digits of `x`.
#[inline]
pub fn owen_scramble(x: u32, seed: u32) -> u32 {
    laine_karras(x.reverse_bits(), seed).reverse_bits()
}

/// The Laine-Karras permutation with Burley's constants: bit `k` of the
/// result depends on bits `0..=k` of `x` only.
#[inline]
fn laine_karras(mut x: u32, seed: u32) -> u32 {
    x = x.wrapping_add(seed);
    for c in [0x6c50_b47c_u32, 0xb82f_1e52, 0xc7af_e638, 0x8d22_f6e6] {
        x ^= x.wrapping_mul(c);
    }
    x
}

/// The value in `[0, 1)` of 32 binary digits (rounded down to an `f32`
/// below 1).
#[inline]
pub fn to_unit(x: u32) -> f32 {
    // The top 24 digits: exact in an f32, and never 1.
    (x >> 8) as f32 * (1.0 / (1u32 << 24) as f32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_byte_tables_equal_the_column_by_column_product() {
        let slow = |mut index: u64| {
            let (mut column, mut x) = (1u32 << 31, 0);
            while index != 0 {
                if index & 1 == 1 {
                    x ^= column;
                }
                column ^= column >> 1;
                index >>= 1;
            }
            x
        };
        for i in (0..1u64 << 16).chain([u64::MAX, 1 << 40, 0xDEAD_BEEF_1234]) {
            let i = i.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> (i % 64);
            assert_eq!(pascal(i), slow(i), "{i:#x}");
        }
    }

    #[test]
    fn pascal_columns_are_binomials_mod_2() {
        // Column j has bit (31 - k) set when binom(j, k) is odd.
        for j in 0..20u64 {
            let mut binom = 1u64; // binom(j, 0)
            let mut column = 0u32;
            for k in 0..=j.min(31) {
                if binom % 2 == 1 {
                    column |= 1 << (31 - k);
                }
                binom = binom * (j - k) / (k + 1);
            }
            assert_eq!(pascal(1 << j), column, "column {j}");
        }
    }

    #[test]
    fn scrambling_is_a_nested_bijection() {
        // Values sharing their first k digits map to values sharing theirs.
        let seed = 0x1234_5678;
        for x in (0..1u32 << 12).map(|i| i.wrapping_mul(0x9E37_79B9)) {
            let y = x ^ 1; // differs in the last digit only
            assert_eq!(owen_scramble(x, seed) >> 1, owen_scramble(y, seed) >> 1);
            let z = x ^ (1 << 20);
            let shared = 32 - 21;
            assert_eq!(
                owen_scramble(x, seed) >> (32 - shared),
                owen_scramble(z, seed) >> (32 - shared)
            );
        }
        let mut seen: Vec<u32> = (0..1u32 << 16)
            .map(|x| owen_scramble(x << 16, seed) >> 16)
            .collect();
        seen.sort_unstable();
        seen.dedup();
        assert_eq!(seen.len(), 1 << 16);
    }

    #[test]
    fn the_reversed_computation_is_the_scramble_of_the_points() {
        for i in (0..4096u64).map(|i| i.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 20) {
            for seed in [0, 0xABCD_0123] {
                let x = owen_scramble(van_der_corput(i), seed);
                assert_eq!(scrambled_sobol(i, 0, seed), x);
                let y = owen_scramble(pascal(i), seed);
                assert_eq!(scrambled_sobol(i, 1, seed), y);
            }
        }
    }

    #[test]
    fn unit_values_stay_below_one() {
        assert_eq!(to_unit(0), 0.0);
        assert!(to_unit(u32::MAX) < 1.0);
    }
}
