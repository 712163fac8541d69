//! The one RNG of placecat, in its own module so that every stage (the
//! simulator, seeding, sampling) takes it from here and none from another.

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// A seeded ChaCha8: it is specified bit for bit, so the same seed gives
/// the same labels natively and in wasm.
pub fn rng(seed: u64) -> ChaCha8Rng {
    ChaCha8Rng::seed_from_u64(seed)
}
