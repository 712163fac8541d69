// The digest of a descriptor that tests/fixtures/descriptor_digests.json
// holds: FNV-1a over its shape, every matrix entry and the summary counts.
// Included (`include!`) by tests/it/descriptor_digests.rs and by the wasm
// tests (tests/wasm_api/descriptor_digests.rs), so both compare the same bits.

fn fnv(words: impl IntoIterator<Item = u32>) -> u64 {
    let mut h = 0xcbf2_9ce4_8422_2325u64;
    for w in words {
        for b in w.to_le_bytes() {
            h = (h ^ b as u64).wrapping_mul(0x0100_0000_01b3);
        }
    }
    h
}

fn digest(d: &placecat::Descriptor) -> String {
    let s = &d.summary;
    let head = [d.rows, d.cols, d.matrices.len()].map(|v| v as u32);
    let tail = [
        s.points,
        s.dropped,
        s.voxels,
        s.sparse_voxels,
        s.spherical,
        s.planar,
        s.linear,
        s.in_range,
        s.alignments,
    ]
    .map(|v| v as u32);
    let body = d.matrices.iter().flatten().copied();
    format!("{:016x}", fnv(head.into_iter().chain(body).chain(tail)))
}
