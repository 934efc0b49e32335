//! Tests of `sampling::zsobol`: the permutation table, the caches
//! against the definition, Morton order and the shuffle's aligned blocks.

use super::*;

#[test]
fn the_table_holds_every_permutation_once() {
    let mut t = PERMUTATIONS.to_vec();
    for p in &t {
        let mut s = *p;
        s.sort_unstable();
        assert_eq!(s, [0, 1, 2, 3]);
    }
    t.sort_unstable();
    t.dedup();
    assert_eq!(t.len(), 24);
}

/// The caches (pixel digits, sample groups) change no number: samples
/// in order, backwards and skipping about, for sample counts with
/// `L` even and odd, against a sampler whose caches are emptied
/// before every sample, so that it computes every digit anew.
#[test]
fn the_caches_change_nothing() {
    for spp in [1, 2, 4, 8, 16, 32, 64] {
        let mut cached = ZSobolSampler::new(9, (64, 64), spp);
        let mut fresh = cached.clone();
        let forwards = (0..spp).map(|i| ((3, 4), i));
        let backwards = (0..spp).rev().map(|i| ((5, 4), i));
        let about = [
            ((3, 4), 0),
            ((3, 4), spp - 1),
            ((6, 1), 0),
            ((3, 4), spp / 2),
        ];
        for (pixel, i) in forwards.chain(backwards).chain(about) {
            cached.start_pixel_sample(pixel, i);
            let from_caches: Vec<Vec2> = (0..40).map(|_| cached.get_2d()).collect();
            fresh = ZSobolSampler {
                cache: [PixelDigits::default(); CACHED_DIMENSIONS],
                groups: [SampleGroup::NONE; CACHED_DIMENSIONS],
                ..fresh
            };
            fresh.start_pixel_sample(pixel, i);
            let anew: Vec<Vec2> = (0..40).map(|_| fresh.get_2d()).collect();
            assert_eq!(from_caches, anew, "spp {spp}, pixel {pixel:?}, sample {i}");
        }
    }
}

/// The shuffled index digit by digit, as the module docs state it:
/// every sample digit permuted by the hash of the digits above it,
/// the last base-2 digit (odd `L`) flipped by a hash bit.
fn index_by_the_definition(s: &ZSobolSampler, dimension: u32) -> u64 {
    let key = DimensionKeys::new(s.seed, dimension).shuffle;
    let odd = s.log2_spp & 1;
    let morton = (s.pixel << s.log2_spp) | s.sample;
    let mut low = 0;
    for i in 0..s.log2_spp / 2 {
        let shift = odd + 2 * i;
        let digit = (s.sample >> shift) & 3;
        low |= permute(morton >> (shift + 2), shift, key, digit) << shift;
    }
    if odd == 1 {
        low |= (s.sample & 1) ^ (splitmix64(((morton >> 1) << 6) ^ key) >> 63);
    }
    (s.shuffle_pixel(key).digits << s.log2_spp) | low
}

/// The index the sampler uses, through its caches, is the one the
/// definition gives, for every sample of two pixels at each sample
/// count, in order and then in a scrambled order that leaves and
/// re-enters groups, in dimensions within and past the cached ones.
#[test]
fn the_shuffled_index_is_the_definitions() {
    for spp in [1, 2, 4, 8, 16, 32, 64, 128] {
        let mut s = ZSobolSampler::new(5, (40, 30), spp);
        let in_order = (0..spp).map(|i| ((0, 0), i));
        let scrambled = (0..spp).map(|i| ((17, 29), (i * 7 + 3) % spp));
        let alternating =
            (0..spp).map(|i| (if i % 2 == 0 { (0, 0) } else { (17, 29) }, (i * 5) % spp));
        for (pixel, i) in in_order.chain(scrambled).chain(alternating) {
            s.start_pixel_sample(pixel, i);
            for dimension in [0, 1, 2, 7, 63, 64, 90] {
                let expected = index_by_the_definition(&s, dimension);
                assert_eq!(
                    s.sequence_index(dimension).0,
                    expected,
                    "spp {spp}, sample {i}, dimension {dimension}"
                );
            }
        }
    }
}

#[test]
fn morton_interleaves() {
    assert_eq!(morton2(0b11, 0), 0b0101);
    assert_eq!(morton2(0, 0b11), 0b1010);
    assert_eq!(morton2(u32::MAX, u32::MAX), u64::MAX);
}

#[test]
fn the_shuffle_maps_a_pixel_onto_one_aligned_block() {
    for spp in [1, 2, 8, 16, 32] {
        let mut s = ZSobolSampler::new(3, (37, 20), spp);
        for ((x, y), dimension) in [((0, 0), 0), ((5, 7), 3), ((36, 19), 70)] {
            let mut indices: Vec<u64> = (0..spp)
                .map(|i| {
                    s.start_pixel_sample((x, y), i);
                    s.sequence_index(dimension).0
                })
                .collect();
            indices.sort_unstable();
            let base = indices[0];
            assert_eq!(base % spp as u64, 0, "aligned");
            assert!(indices
                .iter()
                .enumerate()
                .all(|(i, &v)| v == base + i as u64));
        }
    }
}
