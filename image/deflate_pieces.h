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

/// What deflatePieces compresses: `units` units (a PNG's rows) of
/// `unitBytes` bytes each, unit k given by unit(k, scratch): a pointer to
/// its bytes, or to `scratch` (unitBytes long) once it holds them. It is
/// called from several threads at once, for different units.
struct PieceSource {
  std::size_t units = 0;
  std::size_t unitBytes = 0;
  // A piece is whole units, at least this many bytes where there are.
  std::size_t pieceBytes = std::size_t{1} << 20;
  std::function<const unsigned char*(std::size_t unit, unsigned char* scratch)> unit;
};

/// The zlib stream of `source` at zlib's `level`, its pieces deflated on at
/// most `threads` threads (0: every core); empty if zlib fails (out of
/// memory).
std::string deflatePieces(const PieceSource& source, int level, int threads);

}  // namespace image
