#include "image/deflate_pieces.h"

#include <zlib.h>

#include <algorithm>
#include <vector>

#include "renderer/parallel_parts.h"

namespace image {

namespace {

// One piece deflated: its raw deflate bytes and the Adler-32 of its data.
struct Piece {
  std::string bytes;
  uLong adler = 1;
  std::size_t length = 0;
  bool ok = false;
};

// Deflates `data` as a raw stream at `level`, ended by a sync flush or,
// for the last piece, by the final block.
bool deflateRaw(const unsigned char* data, std::size_t length, int level, bool last,
                std::string& out) {
  z_stream stream{};
  // windowBits -15: raw deflate, no header or check of its own; memLevel 8
  // and the default strategy, as libpng's.
  if (deflateInit2(&stream, level, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) return false;
  // The bound of a whole stream, and a sync flush's empty block.
  out.resize(deflateBound(&stream, static_cast<uLong>(length)) + 16);
  stream.next_in = const_cast<Bytef*>(data);
  stream.avail_in = static_cast<uInt>(length);
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  int status = deflate(&stream, last ? Z_FINISH : Z_SYNC_FLUSH);
  bool ok = last ? status == Z_STREAM_END : status == Z_OK && stream.avail_in == 0;
  out.resize(stream.total_out);
  deflateEnd(&stream);
  return ok;
}

}  // namespace

std::string deflatePieces(const PieceSource& source, int level, int threads) {
  std::size_t unit = std::max<std::size_t>(source.unit, 1);
  std::size_t units = (source.total + unit - 1) / unit;
  // A piece is whole units, at least pieceBytes where there are that many,
  // and at most as many bytes as zlib's uInt counts at once.
  std::size_t perPiece = std::max<std::size_t>(1, (source.pieceBytes + unit - 1) / unit);
  perPiece = std::min<std::size_t>(perPiece, std::max<std::size_t>(1, (1u << 30) / unit));
  std::size_t count = std::max<std::size_t>(1, (units + perPiece - 1) / perPiece);
  std::vector<Piece> pieces(count);
  render::runParts(count, render::resolveThreads(threads), [&](std::size_t k) {
    std::size_t first = std::min(source.total, k * perPiece * unit);
    std::size_t end = std::min(source.total, (k + 1) * perPiece * unit);
    Piece& piece = pieces[k];
    piece.length = end - first;
    std::vector<unsigned char> data(piece.length);
    if (piece.length > 0) source.makePiece(first, piece.length, data.data());
    piece.adler = adler32(1L, data.data(), static_cast<uInt>(data.size()));
    piece.ok = deflateRaw(data.data(), data.size(), level, k + 1 == count, piece.bytes);
  });
  std::size_t size = 6;
  for (const Piece& piece : pieces) {
    if (!piece.ok) return {};
    size += piece.bytes.size();
  }
  std::string stream;
  stream.reserve(size);
  // zlib's header: deflate with a 32 KiB window (0x78), and a check that
  // makes the pair a multiple of 31, the level marked as zlib marks it.
  unsigned flags = level == 1 || level == 0 ? 0 : level < 6 ? 1 : level == 6 ? 2 : 3;
  unsigned header = (0x78u << 8) | (flags << 6);
  header += (31 - header % 31) % 31;
  stream.push_back(static_cast<char>(header >> 8));
  stream.push_back(static_cast<char>(header & 0xff));
  uLong adler = 1;
  for (const Piece& piece : pieces) {
    stream += piece.bytes;
    adler = adler32_combine(adler, piece.adler, static_cast<z_off_t>(piece.length));
  }
  for (int shift = 24; shift >= 0; shift -= 8) {
    stream.push_back(static_cast<char>((adler >> shift) & 0xff));
  }
  return stream;
}

}  // namespace image
