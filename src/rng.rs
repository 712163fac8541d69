//! The one RNG of placecat, in its own module so that every stage (the
//! simulator, seeding, sampling) takes it from here and none from another.

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// A seeded ChaCha8: it is specified bit for bit, so the same seed gives
/// the same labels natively and in wasm.
pub fn rng(seed: u64) -> ChaCha8Rng {
    ChaCha8Rng::seed_from_u64(seed)
}

/// Stream `stream` of the ChaCha8 seeded with `seed`: independent draws
/// from one user seed (k-means restart r takes stream r). Stream 0 is
/// [`rng`]'s own, so `rng_stream(seed, 0)` draws exactly what `rng(seed)` does.
pub fn rng_stream(seed: u64, stream: u64) -> ChaCha8Rng {
    let mut r = rng(seed);
    r.set_stream(stream);
    r
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::Rng;

    #[test]
    fn stream_zero_draws_what_the_plain_rng_draws() {
        let (mut a, mut b) = (rng(42), rng_stream(42, 0));
        let (mut c, mut d) = (rng(42), rng_stream(42, 1));
        for _ in 0..64 {
            assert_eq!(a.random::<u64>(), b.random::<u64>());
        }
        let same = (0..64)
            .filter(|_| c.random::<u64>() == d.random::<u64>())
            .count();
        assert_eq!(same, 0, "stream 1 is another sequence");
    }
}
