// A zlib stream (RFC 1950) made of pieces deflated apart, on several
// threads: each piece a raw deflate stream of its own, every one but the
// last ended by a sync flush (an empty stored block, which leaves the bits
// on a byte boundary and the stream open), so that their concatenation,
// between zlib's header and the Adler-32 of the whole (adler32_combine),
// is one valid stream, as pigz makes. The pieces are fixed by the data's
// size alone, so the bytes are the same for any thread count; each piece
// starts without the history of the one before it, which costs a few
// hundred bytes a piece of an image's megabytes.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace image {

/// What deflatePieces compresses: `total` bytes, of which makePiece(first,
/// count, out) writes bytes [first, first + count) into out[0, count). It
/// is called from several threads at once, for different ranges.
struct PieceSource {
  std::size_t total = 0;
  // The piece boundaries are multiples of `unit` (a PNG row, say), at
  // least `pieceBytes` apart, where the data allows.
  std::size_t unit = 1;
  std::size_t pieceBytes = std::size_t{1} << 20;
  std::function<void(std::size_t first, std::size_t count, unsigned char* out)> makePiece;
};

/// The zlib stream of `source` at zlib's `level`, its pieces deflated on at
/// most `threads` threads (0: every core); empty if zlib fails (out of
/// memory).
std::string deflatePieces(const PieceSource& source, int level, int threads);

}  // namespace image
