//! LZF compression, the format of liblzf that PCL's `binary_compressed` PCD
//! files use.
//!
//! Written here, not taken from the `lzf` crate (which the PCD reader still
//! uses to decompress): `lzf` 1.0.0's `compress` panics (index out of
//! bounds, compress.rs:89) on some inputs, e.g. 64 random points written by
//! the readers' round-trip property test, and a writer must not panic.

/// Bits of the hash table of 3-byte prefixes.
const HASH_BITS: u32 = 14;
/// Farthest back a reference can point (13 bits of offset - 1).
const MAX_DISTANCE: usize = 1 << 13;
/// Longest reference: 2 + 7 + 255 bytes.
const MAX_MATCH: usize = 264;
/// Longest literal run (a control byte 0..=31).
const MAX_LITERALS: usize = 32;

/// Compress `input` into an LZF stream that liblzf (and `lzf::decompress`)
/// expands back to `input`. Greedy: at each position, the last earlier
/// position with the same three bytes, if near enough, becomes a reference.
pub(crate) fn compress(input: &[u8]) -> Vec<u8> {
    let n = input.len();
    let mut out = Vec::with_capacity(n + n / MAX_LITERALS + 1);
    let mut last_seen = vec![usize::MAX; 1 << HASH_BITS];
    let mut literals_from = 0;
    let mut i = 0;
    while i + 3 <= n {
        let slot = hash(&input[i..i + 3]);
        let earlier = last_seen[slot];
        last_seen[slot] = i;
        let near = earlier != usize::MAX && i - earlier <= MAX_DISTANCE;
        if !near || input[earlier..earlier + 3] != input[i..i + 3] {
            i += 1;
            continue;
        }
        // The copy may overlap what it writes (a run): liblzf copies byte by byte.
        let longest = (n - i).min(MAX_MATCH);
        let mut len = 3;
        while len < longest && input[earlier + len] == input[i + len] {
            len += 1;
        }
        push_literals(&mut out, &input[literals_from..i]);
        let offset = i - earlier - 1;
        let stored = len - 2; // 1..=262: never 0, which would read as a literal run
        let high = (offset >> 8) as u8;
        if stored < 7 {
            out.push(((stored as u8) << 5) | high);
        } else {
            out.push((7 << 5) | high);
            out.push((stored - 7) as u8);
        }
        out.push((offset & 0xff) as u8);
        i += len;
        literals_from = i;
    }
    push_literals(&mut out, &input[literals_from..]);
    out
}

/// Literal runs of at most 32 bytes, each after its control byte (length - 1).
fn push_literals(out: &mut Vec<u8>, bytes: &[u8]) {
    for run in bytes.chunks(MAX_LITERALS) {
        out.push((run.len() - 1) as u8);
        out.extend_from_slice(run);
    }
}

/// Slot of a 3-byte prefix (Fibonacci hashing).
fn hash(three: &[u8]) -> usize {
    let v = u32::from(three[0]) << 16 | u32::from(three[1]) << 8 | u32::from(three[2]);
    (v.wrapping_mul(2_654_435_761) >> (32 - HASH_BITS)) as usize
}

#[cfg(test)]
mod tests {
    use super::compress;

    fn round_trip(input: &[u8]) -> Vec<u8> {
        let packed = compress(input);
        lzf::decompress(&packed, input.len()).expect("lzf decompresses our stream")
    }

    #[test]
    fn runs_repeats_and_noise_come_back_and_repeats_shrink() {
        let zeros = vec![0u8; 10_000];
        assert_eq!(round_trip(&zeros), zeros);
        assert!(compress(&zeros).len() < 200, "a run of zeros shrinks");
        let pattern: Vec<u8> = (0..20_000u32).map(|i| (i % 97) as u8).collect();
        assert_eq!(round_trip(&pattern), pattern);
        assert!(compress(&pattern).len() < 1_000);
        let mut state = 12345u32;
        let noise: Vec<u8> = (0..5_000)
            .map(|_| {
                state = state.wrapping_mul(1_103_515_245).wrapping_add(12_345);
                (state >> 24) as u8
            })
            .collect();
        assert_eq!(round_trip(&noise), noise);
        // (An empty stream is no LZF stream for `lzf::decompress`; the PCD
        // reader handles zero points before decompressing.)
        assert!(compress(&[]).is_empty());
        for len in 1..8 {
            assert_eq!(round_trip(&noise[..len]), &noise[..len]);
        }
        // References 8192 bytes back, the farthest the format allows.
        let mut far = noise.clone();
        far.extend_from_slice(&vec![7u8; 8192 - noise.len()]);
        far.extend_from_slice(&noise[..300]);
        assert_eq!(round_trip(&far), far);
    }
}
