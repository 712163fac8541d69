//! Chunk decompression, in pure Rust so the same code runs in wasm32:
//! bz2 (ROS 1) with `bzip2` on libbz2-rs-sys, lz4 frames (ROS 1's roslz4 and
//! MCAP's lz4) with `lz4_flex`, zstd (MCAP) with `ruzstd`.

use crate::error::{Error, Result};
use std::io::Read;

/// Decompress `src` (compressed with `compression`, as named in the chunk
/// header) into `dst`, which must come out exactly `size` bytes long: fewer
/// means the chunk was cut short, more that its header lies.
pub(crate) fn decompress(
    compression: &str,
    src: &[u8],
    size: usize,
    dst: &mut Vec<u8>,
) -> Result<()> {
    dst.clear();
    // A lying header must not make a huge allocation before any byte is
    // decoded: reserve at most 64 MiB up front, grow past it as data comes.
    dst.reserve_exact(size.min(64 << 20));
    // One byte more than announced is read so an overlong chunk shows.
    let limit = size as u64 + 1;
    let res = match compression {
        "" | "none" => {
            dst.extend_from_slice(src);
            Ok(dst.len())
        }
        "bz2" => bzip2::read::BzDecoder::new(src)
            .take(limit)
            .read_to_end(dst),
        "lz4" => lz4_flex::frame::FrameDecoder::new(src)
            .take(limit)
            .read_to_end(dst),
        "zstd" => match ruzstd::StreamingDecoder::new(src) {
            Ok(d) => d.take(limit).read_to_end(dst),
            Err(e) => Err(std::io::Error::other(e.to_string())),
        },
        other => {
            return Err(Error::Bag(format!(
                "unknown chunk compression {other:?} (placecat reads none, bz2, lz4 and zstd)"
            )))
        }
    };
    match res {
        Err(e) => Err(Error::Bag(format!(
            "{compression} chunk cannot be decompressed, truncated or corrupt ({e})"
        ))),
        Ok(_) if dst.len() != size => Err(Error::Bag(format!(
            "truncated chunk: {compression} data decompressed to {} bytes, the chunk header \
             says {size}",
            dst.len()
        ))),
        Ok(_) => Ok(()),
    }
}
