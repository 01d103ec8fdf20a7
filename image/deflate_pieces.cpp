#include "image/deflate_pieces.h"

#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <memory>
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

// One thread's deflater, reset for each of its pieces: its state (a third
// of a megabyte) and buffers are made once, as fresh memory costs a page
// fault a page, which at 1080p cost more than the deflating saved.
class PieceDeflater {
 public:
  PieceDeflater(const PieceSource& source, int level)
      : source_(source), scratch_(source.unitBytes) {
    // windowBits -15: raw deflate, no header or check of its own; memLevel
    // 8 and the default strategy, as libpng's.
    ready_ = deflateInit2(&stream_, level, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) == Z_OK;
  }
  ~PieceDeflater() {
    if (ready_) deflateEnd(&stream_);
  }
  PieceDeflater(const PieceDeflater&) = delete;
  PieceDeflater& operator=(const PieceDeflater&) = delete;

  // Units [first, end) into `piece`, ended by a sync flush, or by the final
  // block where `last`.
  void deflatePiece(std::size_t first, std::size_t end, bool last, Piece& piece) {
    if (!ready_ || deflateReset(&stream_) != Z_OK) return;
    piece.length = (end - first) * source_.unitBytes;
    for (std::size_t k = first; k < end; ++k) {
      const unsigned char* data = source_.unit(k, scratch_.data());
      piece.adler = adler32(piece.adler, data, static_cast<uInt>(source_.unitBytes));
      stream_.next_in = const_cast<Bytef*>(data);
      stream_.avail_in = static_cast<uInt>(source_.unitBytes);
      if (!run(Z_NO_FLUSH, piece.bytes)) return;
    }
    piece.ok = run(last ? Z_FINISH : Z_SYNC_FLUSH, piece.bytes);
  }

 private:
  // deflate with `flush` until the input is taken and, when flushing, all
  // of the output is out, appended to `out`.
  bool run(int flush, std::string& out) {
    while (true) {
      stream_.next_out = out_;
      stream_.avail_out = sizeof out_;
      int status = deflate(&stream_, flush);
      out.append(reinterpret_cast<const char*>(out_), sizeof out_ - stream_.avail_out);
      if (status == Z_STREAM_END) return true;
      if (status != Z_OK && status != Z_BUF_ERROR) return false;
      if (stream_.avail_out != 0 && stream_.avail_in == 0) return flush != Z_FINISH;
    }
  }

  const PieceSource& source_;
  std::vector<unsigned char> scratch_;
  z_stream stream_{};
  bool ready_ = false;
  Bytef out_[1 << 16];
};

}  // namespace

std::string deflatePieces(const PieceSource& source, int level, int threads) {
  std::size_t unitBytes = std::max<std::size_t>(source.unitBytes, 1);
  // At most as many bytes a piece as zlib's uInt counts at once.
  std::size_t perPiece = std::max<std::size_t>(1, (source.pieceBytes + unitBytes - 1) / unitBytes);
  perPiece = std::min<std::size_t>(perPiece, std::max<std::size_t>(1, (1u << 30) / unitBytes));
  std::size_t count = std::max<std::size_t>(1, (source.units + perPiece - 1) / perPiece);
  std::vector<Piece> pieces(count);
  std::size_t workers =
      std::min<std::size_t>(count, static_cast<std::size_t>(render::resolveThreads(threads)));
  std::atomic<std::size_t> next{0};
  render::runParts(workers, static_cast<int>(workers), [&](std::size_t) {
    auto deflater = std::make_unique<PieceDeflater>(source, level);
    for (std::size_t k = next++; k < count; k = next++) {
      deflater->deflatePiece(std::min(source.units, k * perPiece),
                             std::min(source.units, (k + 1) * perPiece), k + 1 == count, pieces[k]);
    }
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
