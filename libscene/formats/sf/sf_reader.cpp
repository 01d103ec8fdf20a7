#include "libscene/formats/sf/sf_reader.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>
#include <optional>
#include <thread>
#include <vector>

#include "libscene/core/finite_check.h"
#include "libscene/core/populate_pages.h"
#include "libscene/core/run_on_threads.h"
#include "libscene/text/reader_support.h"
#include "libscene/text/text_lines.h"
#include "scenefile/validation.h"

namespace scene {

namespace {

// The records: CAMERA, LIGHT, then one per object kind, in the order of
// scenefile/object_kinds.def.
enum class RecordKind : std::uint8_t {
  Camera,
  Light,
#define SCENEFILE_OBJECT_KIND(enumerator, record, pov) enumerator,
#include "scenefile/object_kinds.def"
#undef SCENEFILE_OBJECT_KIND
  Unknown
};

constexpr std::string_view kRecordNames[] = {
    "CAMERA",
    "LIGHT",
#define SCENEFILE_OBJECT_KIND(enumerator, record, pov) #record,
#include "scenefile/object_kinds.def"
#undef SCENEFILE_OBJECT_KIND
};

std::string expectedRecord() {
  return "a record name (CAMERA, LIGHT, " + objectKindChoices() + ")";
}

RecordKind recordKindFromName(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kRecordNames); ++i) {
    if (kRecordNames[i] == name) return static_cast<RecordKind>(i);
  }
  return RecordKind::Unknown;
}

// The object kind of a record past LIGHT: those follow the kinds' order.
ObjectKind objectKindOf(RecordKind kind) {
  constexpr auto kFirstObject = static_cast<std::size_t>(RecordKind::Light) + 1;
  return kObjectKinds[static_cast<std::size_t>(kind) - kFirstObject];
}

bool startsLikeNumber(std::string_view token) {
  char c = token.front();
  return (c >= '0' && c <= '9') || c == '.' || c == '+' || c == '-';
}

// A text's lines (its newlines) and an upper bound on the records it can
// hold, for one allocation up front: every record starts with a line that
// starts with a letter.
struct TextCounts {
  std::size_t lines = 0;
  std::size_t records = 0;
};

// Both counts in one pass over the text, branch-free over pairs of bytes,
// in blocks whose 32-bit sums the compiler vectorises: a loop that branched
// on every byte took near a tenth of the whole parse, and a pass for each
// count took 28 ms at 1,000,000 objects, 13 ms more than one pass.
TextCounts countLinesAndRecords(std::string_view text) {
  TextCounts counts;
  if (text.empty()) return counts;
  const unsigned char* bytes = reinterpret_cast<const unsigned char*>(text.data());
  counts.records = static_cast<unsigned char>(bytes[0] - 'A') < 26u;
  counts.lines = bytes[text.size() - 1] == '\n';
  constexpr std::size_t kBlock = 4096;
  for (std::size_t i = 1; i < text.size();) {
    std::size_t stop = std::min(text.size(), i + kBlock);
    std::uint32_t newlines = 0;
    std::uint32_t starts = 0;
    for (; i < stop; ++i) {
      std::uint32_t newline = bytes[i - 1] == '\n';
      newlines += newline;
      starts += newline & (static_cast<unsigned char>(bytes[i] - 'A') < 26u);
    }
    counts.lines += newlines;
    counts.records += starts;
  }
  return counts;
}

// The records to make room for, capped so that a hostile count costs no
// more than a growing vector would.
std::size_t recordsToReserve(const TextCounts& counts) {
  return std::min<std::size_t>(counts.records, std::size_t{1} << 22);
}

using PartFacts = SceneFilePartFacts;

// How many objects' room a part faults in at a time: 4 MB.
constexpr std::size_t kObjectsPopulatedAhead = (std::size_t{4} << 20) / sizeof(Object);

class SceneFileParser {
 public:
  SceneFileParser(std::string_view text, const ReadOptions& options, ReadResult& result)
      : SceneFileParser(
            text, options, result, 1,
            // A read asked to stop reads nothing: no room made.
            options.stop.stop_requested() ? 0 : recordsToReserve(countLinesAndRecords(text))) {}

  // A part of a file (parseSceneFileInParts): `firstLine` is the number of
  // its first line in the file, and `records` the records to make room for.
  SceneFileParser(std::string_view text, const ReadOptions& options, ReadResult& result,
                  std::uint32_t firstLine, std::size_t records)
      : cursor_(text, firstLine),
        options_(options),
        scene_(result.scene),
        out_(result.diagnostics) {
    scene_.objects.reserve(std::min(records, options.maxObjects));
  }

  void run() {
    readRecords();
    finish();
  }

  // Reads the text as a part of a file: its records, without the checks
  // that need the whole file, up to the first diagnostic of any kind.
  PartFacts runPart() {
    readingPart_ = true;
    readRecords();
    return PartFacts{firstRecord_.has_value(), firstIsCamera_, cameraNamed_, objectsSeen_};
  }

 private:
  void readRecords() {
    while (!out_.full() && !stopped_ && !(readingPart_ && !out_.empty()) && pull()) {
      if (++recordsSinceStopCheck_ == kRecordsPerStopCheck) {
        recordsSinceStopCheck_ = 0;
        if (options_.stop.stop_requested()) {
          stopped_ = true;
          return;
        }
      }
      if (cursor_.blank() || reportComment(cursor_, out_)) continue;
      if (reportInvalidByte(cursor_, out_)) {
        // Most likely a damaged record name: its body follows, and reading
        // it as a record of no kind keeps its lines from being misread.
        resyncing_ = false;
        readBody(RecordKind::Unknown, "damaged", cursor_.lineSpan(), true);
        continue;
      }
      parseRecord();
    }
  }

  // The next line, or the one a truncated record left for the next record.
  bool pull() {
    if (pending_) {
      pending_ = false;
      return true;
    }
    return cursor_.next();
  }

  void parseRecord() {
    std::string_view name = cursor_.token(0).text;
    SourceSpan nameSpan = cursor_.tokenSpan(0);
    RecordKind kind = recordKindFromName(name);
    if (kind == RecordKind::Unknown) {
      if (startsLikeNumber(name)) {
        // Stray numbers: report once, then skip to the next named line.
        if (!resyncing_) {
          out_.error(DiagnosticCode::ExpectedRecordName, nameSpan,
                     "expected " + expectedRecord() + ", found a number")
              .hint = "each record is a name line, a colour line and four matrix rows";
        }
        resyncing_ = true;
        return;
      }
      reportUnknownKeyword(cursor_, 0, kRecordNames, expectedRecord(), out_);
      // "sphere" is still a sphere for the rest of the checks.
      if (auto guess = suggestKeyword(name, kRecordNames); guess && guess->size() == name.size()) {
        kind = recordKindFromName(*guess);
      }
    }
    resyncing_ = false;
    if (kind != RecordKind::Camera && kind != RecordKind::Unknown &&
        ++objectsSeen_ > options_.maxObjects) {
      reportTooManyObjects(nameSpan, options_.maxObjects, out_);
      stopped_ = true;
      return;
    }
    if (cursor_.tokenCount() > 1) {
      out_.error(DiagnosticCode::TokenCount, cursor_.tokenSpan(1),
                 "a record name stands alone on its line");
    }
    noteRecordOrder(kind, nameSpan);
    // A CAMERA with a bad number or a missing line is still the file's
    // camera: its own error says what is wrong, "no CAMERA record" would not.
    if (kind == RecordKind::Camera) cameraNamed_ = true;
    readBody(kind, name, nameSpan, false);
  }

  // The colour line and the four matrix rows of a record whose name line is
  // the cursor's; `damaged` when that line was unreadable, and then a record
  // cut short goes unreported (the damage is the error).
  void readBody(RecordKind kind, std::string_view name, SourceSpan nameSpan, bool damaged) {
    // Every value and span is written before it is used: a record lacking
    // any of them is not added. Hence no clearing, which costs more per
    // record than the writing.
    std::array<double, 3> colour;
    std::array<double, 16> rows;
    spans_.record = nameSpan;
    bool valuesOk = true;
    bool blankReported = false;
    int linesRead = 0;
    while (linesRead < 5) {
      // The colour line, then the four matrix rows, their spans as written.
      std::size_t count = linesRead == 0 ? 3 : 4;
      double* values = linesRead == 0 ? colour.data() : rows.data() + 4 * (linesRead - 1);
      SourceSpan* where =
          linesRead == 0 ? spans_.colour.data() : spans_.matrix.data() + 4 * (linesRead - 1);
      // Nearly every line is just its numbers, read in one pass; any other
      // line is split into tokens and looked at with care.
      if (readPlainNumberLine(cursor_, count, values, where)) {
        ++linesRead;
        continue;
      }
      if (!cursor_.nextLine()) {
        if (!damaged) reportTruncated(name, nameSpan, linesRead, "the file ends");
        return;
      }
      cursor_.tokenize();
      if (cursor_.blank()) {
        if (!blankReported) {
          out_.error(DiagnosticCode::BlankLineInRecord, cursor_.endOfLine(),
                     "blank line inside a " + std::string(name) + " record")
              .notes.push_back({nameSpan, "the record starts here"});
          blankReported = true;
        }
        continue;
      }
      if (reportComment(cursor_, out_)) continue;
      if (recordKindFromName(cursor_.token(0).text) != RecordKind::Unknown) {
        if (!damaged) reportTruncated(name, nameSpan, linesRead, "the next record starts");
        pending_ = true;
        return;
      }
      ++linesRead;
      if (reportInvalidByte(cursor_, out_)) {
        valuesOk = false;
        continue;
      }
      static constexpr std::string_view kLineNames[] = {
          "the colour line", "matrix row 1", "matrix row 2", "matrix row 3", "matrix row 4"};
      if (readNumbers(cursor_, 0, count, values, kLineNames[linesRead - 1], out_)) {
        for (std::size_t i = 0; i < count; ++i) where[i] = cursor_.tokenSpan(i);
      } else {
        valuesOk = false;
      }
    }
    if (!valuesOk || kind == RecordKind::Unknown) return;

    glm::dmat4 matrix;
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        // GLM is column-major (matrix[c][r]); the file is row by row.
        double value = rows[r * 4 + c];
        if (options_.sceneFile.transposedMatrices) {
          matrix[r][c] = value;
        } else {
          matrix[c][r] = value;
        }
      }
    }
    // Spans are kept by matrix position, which a transposed file swaps.
    if (options_.sceneFile.transposedMatrices) {
      for (int r = 0; r < 4; ++r) {
        for (int c = r + 1; c < 4; ++c) {
          std::swap(spans_.matrix[r * 4 + c], spans_.matrix[c * 4 + r]);
        }
      }
    }
    glm::dvec3 rgb(colour[0], colour[1], colour[2]);
    addRecord(kind, rgb, matrix, spans_);
  }

  void addRecord(RecordKind kind, const glm::dvec3& colour, const glm::dmat4& matrix,
                 const RecordSpans& spans) {
    switch (kind) {
      case RecordKind::Camera:
        checkMatrixLastRow(matrix, spans, out_);
        checkCameraMatrix(matrix, spans.record, out_);
        if (cameraSpan_) {
          out_.error(DiagnosticCode::DuplicateCamera, spans.record,
                     "a scene has exactly one CAMERA")
              .notes.push_back({*cameraSpan_, "the first CAMERA is here"});
          return;
        }
        cameraSpan_ = spans.record;
        scene_.camera = Camera{matrix, colour, std::nullopt, spans.record};
        return;
      case RecordKind::Light:
        checkColour(colour, RecordRole::Light, spans, out_);
        checkMatrixLastRow(matrix, spans, out_);
        scene_.lights.push_back(Light{matrix, colour, spans.record});
        return;
      default: {
        ObjectKind objectKind = objectKindOf(kind);
        checkColour(colour, RecordRole::Object, spans, out_);
        checkMatrixLastRow(matrix, spans, out_);
        checkObjectMatrix(matrix, objectKindName(objectKind), spans.record, out_);
        Object object;
        object.kind = objectKind;
        object.material.colour = colour;
        object.matrix = matrix;
        object.span = spans.record;
        if (readingPart_) populateRoomAhead();
        scene_.objects.push_back(std::move(object));
        return;
      }
    }
  }

  // A part's room for its next kObjectsPopulatedAhead objects, faulted in
  // at once when the objects reach the end of what was faulted in so far:
  // a fresh page costs more to fault in write by write than the object
  // written there (docs/history/PERFORMANCE.md, "Big scenes: bins, planes
  // and pages"), and room only just ahead of the objects costs no memory for
  // lines that only look like records.
  void populateRoomAhead() {
    std::vector<Object>& objects = scene_.objects;
    if (objects.size() < populatedUpTo_) return;
    std::size_t to = std::min(objects.capacity(), populatedUpTo_ + kObjectsPopulatedAhead);
    populatePagesForWriting(objects.data() + populatedUpTo_, objects.data() + to);
    populatedUpTo_ = to;
  }

  void noteRecordOrder(RecordKind kind, SourceSpan span) {
    if (firstRecord_) return;
    firstRecord_ = span;
    firstIsCamera_ = kind == RecordKind::Camera;
    firstName_ = std::string(cursor_.token(0).text.substr(0, 40));
  }

  void reportTruncated(std::string_view name, SourceSpan nameSpan, int linesRead,
                       std::string_view why) {
    out_.error(DiagnosticCode::TruncatedRecord, nameSpan,
               std::string(name) + " record has " + std::to_string(linesRead + 1) +
                   " of its 6 lines: " + std::string(why))
        .hint = "a record is its name, a colour line and four matrix rows";
  }

  void finish() {
    if (out_.full() || stopped_) return;
    if (!firstRecord_) {
      out_.error(DiagnosticCode::MissingCamera, SourceSpan{1, 1, 0},
                 out_.hasErrors() ? "scene has no CAMERA record" : "file holds no records")
          .hint = "a scene file starts with a CAMERA record, an instruction file with OUTPUT_FILE";
      return;
    }
    if (!cameraSpan_ && !cameraNamed_) {
      out_.error(DiagnosticCode::MissingCamera, *firstRecord_, "scene has no CAMERA record").hint =
          "the first record of a scene file must be the CAMERA";
    } else if (!firstIsCamera_ && cameraSpan_) {
      out_.error(DiagnosticCode::CameraNotFirst, *firstRecord_,
                 "the first record must be the CAMERA, not " + firstName_)
          .notes.push_back({*cameraSpan_, "the CAMERA is here"});
    }
    if (!out_.hasErrors()) checkSceneLevel(scene_, out_);
  }

  LineCursor cursor_;
  const ReadOptions& options_;
  Scene& scene_;
  DiagnosticList& out_;
  bool pending_ = false;
  bool resyncing_ = false;
  // Objects and lights named so far, read or not, against maxObjects.
  std::size_t objectsSeen_ = 0;
  bool stopped_ = false;  // past maxObjects, or asked to stop: nothing more is read
  // Asked to stop is looked at every few thousand records (ReadOptions::stop):
  // an atomic load a record would cost as much as reading some of them.
  static constexpr std::uint32_t kRecordsPerStopCheck = 4096;
  std::uint32_t recordsSinceStopCheck_ = kRecordsPerStopCheck - 1;
  // A part of a file (runPart): it stops at its first diagnostic, and
  // faults in its objects' room ahead of them.
  bool readingPart_ = false;
  std::size_t populatedUpTo_ = 0;  // objects whose room is faulted in
  std::optional<SourceSpan> firstRecord_;
  bool firstIsCamera_ = false;
  std::string firstName_;
  std::optional<SourceSpan> cameraSpan_;
  bool cameraNamed_ = false;  // a CAMERA record was named, read cleanly or not
  // Where the values of the record being read stand, for its diagnostics.
  RecordSpans spans_;
};

// Where a file is cut into `parts` parts: at the start of a
// line that starts with a capital letter (a record name, in a valid file)
// at or after each k / parts of the way; fewer parts where no such line is
// found. The first part starts at 0, and the last ends at the text's end.
std::vector<std::size_t> partStarts(std::string_view text, unsigned parts) {
  std::vector<std::size_t> starts{0};
  for (unsigned k = 1; k < parts; ++k) {
    std::size_t at = std::max(starts.back() + 1, text.size() / parts * k);
    while (at < text.size()) {
      at = text.find('\n', at);
      if (at == std::string_view::npos || at + 1 >= text.size()) {
        at = text.size();
        break;
      }
      ++at;
      if (text[at] >= 'A' && text[at] <= 'Z') break;
    }
    if (at >= text.size()) break;
    starts.push_back(at);
  }
  return starts;
}

// The first part's room for the later parts' objects, faulted in on a
// thread a part before they are moved there: moving them into fresh pages
// on one thread was a sixth of the reading at 1,000,000 objects.
void populateMergeTarget(const std::vector<ReadResult>& results, std::size_t threads) {
  const std::vector<Object>& first = results[0].scene.objects;
  std::size_t later = 0;
  for (std::size_t k = 1; k < results.size(); ++k) later += results[k].scene.objects.size();
  if (first.capacity() - first.size() < later) return;  // the move takes new room
  const Object* from = first.data() + first.size();
  runOnThreads(threads, [&](std::size_t k) {
    populatePagesForWriting(from + later * k / threads, from + later * (k + 1) / threads);
  });
}

}  // namespace

std::span<const std::string_view> sceneFileRecordNames() {
  return kRecordNames;
}

namespace {

// Each part's lines and records (for where the next parts' lines start, and
// for the room each part makes for its objects), then the parts themselves,
// on as many threads: `text` cut at `starts` (and its end), its first line
// the file's line `firstLine`. Each result is emptied, its objects' room
// kept. With `roomForAll`, the first part makes room for every part's
// objects (moving them into a vector of their own costs a tenth of the
// reading). False where a thread could not start or the read was asked to
// stop.
bool readPartsOnThreads(std::string_view text, std::span<const std::size_t> starts,
                        std::uint32_t firstLine, const ReadOptions& options, bool roomForAll,
                        bool checkFinite, std::vector<ReadResult>& results,
                        std::vector<PartFacts>& facts, std::vector<std::uint32_t>& lines) {
  const std::size_t count = starts.size();
  auto part = [&](std::size_t k) {
    std::size_t end = k + 1 < count ? starts[k + 1] : text.size();
    return text.substr(starts[k], end - starts[k]);
  };
  lines.assign(count, 0);
  std::vector<std::size_t> records(count, 0);
  bool counted = runOnThreads(count, [&](std::size_t k) {
    TextCounts counts = countLinesAndRecords(part(k));
    lines[k] = static_cast<std::uint32_t>(counts.lines);
    records[k] = recordsToReserve(counts);
  });
  if (!counted) return false;
  std::vector<std::uint32_t> partLine(count, firstLine);
  std::size_t allRecords = records[0];
  for (std::size_t k = 1; k < count; ++k) {
    partLine[k] = partLine[k - 1] + lines[k - 1];
    allRecords += records[k];
  }
  if (roomForAll) records[0] = allRecords;

  // A part stops at its first diagnostic: any diagnostic sends the file to
  // the whole-file reader, whose diagnostics are the ones reported. Each
  // part's objects get their room here, on this thread, though the part's
  // own thread fills it: glibc may hand out again what this thread frees,
  // where a big block of a part's thread goes back to the system when
  // freed, to be zeroed afresh for the next big array.
  results.resize(count, ReadResult{Scene{}, DiagnosticList({}, options.errorLimit)});
  for (std::size_t k = 0; k < count; ++k) {
    std::vector<Object> room = std::move(results[k].scene.objects);
    room.clear();
    results[k] = ReadResult{Scene{}, DiagnosticList({}, options.errorLimit)};
    results[k].scene.objects = std::move(room);
    std::vector<Object>& objects = results[k].scene.objects;
    objects.reserve(std::min(records[k], options.maxObjects));
    adviseHugePages(objects.data(), objects.data() + objects.capacity());
  }
  facts.assign(count, PartFacts{});
  bool read = runOnThreads(count, [&](std::size_t k) {
    facts[k] = SceneFileParser(part(k), options, results[k], partLine[k], records[k]).runPart();
    if (checkFinite && results[k].diagnostics.empty()) {
      facts[k].finite = objectsFinite(results[k].scene.objects, 1);
    }
  });
  // A stopped read's parts are cut short anywhere: the whole-file reader
  // stops at once, where it checks first.
  return read && !options.stop.stop_requested();
}

// The parts make their text's scene only where each read cleanly, the
// CAMERA came first in the file's first part and nowhere else, and all of
// them together, after `objectsBefore`, hold no more objects than allowed,
// and none holds an object found not finite;
// then the objects and lights they named, else nothing.
std::optional<std::size_t> cleanPartsObjects(const std::vector<ReadResult>& results,
                                             const std::vector<PartFacts>& facts, bool firstOfFile,
                                             std::size_t objectsBefore,
                                             const ReadOptions& options) {
  std::size_t objectsSeen = 0;
  for (std::size_t k = 0; k < results.size(); ++k) {
    if (!results[k].diagnostics.empty() || !facts[k].anyRecord || !facts[k].finite) {
      return std::nullopt;
    }
    bool cameraHere = k == 0 && firstOfFile;
    if (cameraHere ? !facts[k].firstIsCamera : facts[k].cameraNamed) return std::nullopt;
    objectsSeen += facts[k].objectsSeen;
  }
  if (objectsSeen > options.maxObjects || objectsBefore > options.maxObjects - objectsSeen) {
    return std::nullopt;
  }
  return objectsSeen;
}

}  // namespace

std::optional<ReadResult> parseSceneFileInParts(std::string_view text, std::string fileName,
                                                const ReadOptions& options, unsigned parts) {
  std::vector<std::size_t> starts = partStarts(text, parts);
  if (starts.size() < 2) return std::nullopt;
  std::vector<ReadResult> results;
  std::vector<PartFacts> facts;
  std::vector<std::uint32_t> lines;
  if (!readPartsOnThreads(text, starts, 1, options, true, false, results, facts, lines) ||
      !cleanPartsObjects(results, facts, true, 0, options)) {
    return std::nullopt;
  }
  populateMergeTarget(results, results.size());
  ReadResult merged{std::move(results[0].scene),
                    DiagnosticList(std::move(fileName), options.errorLimit)};
  for (std::size_t k = 1; k < results.size(); ++k) {
    Scene& scene = results[k].scene;
    merged.scene.lights.insert(merged.scene.lights.end(), scene.lights.begin(), scene.lights.end());
    merged.scene.objects.insert(merged.scene.objects.end(),
                                std::make_move_iterator(scene.objects.begin()),
                                std::make_move_iterator(scene.objects.end()));
  }
  // The whole-file check of a clean file (SceneFileParser::finish).
  checkSceneLevel(merged.scene, merged.diagnostics);
  return merged;
}

bool parseSceneFileWindow(const SceneFileWindow& window, const ReadOptions& options, unsigned parts,
                          SceneFileWindowRead& read) {
  std::vector<std::size_t> starts = partStarts(window.text, std::max(parts, 1u));
  if (!readPartsOnThreads(window.text, starts, window.firstLine, options, false, true, read.parts,
                          read.facts, read.partLines)) {
    return false;
  }
  std::optional<std::size_t> objects =
      cleanPartsObjects(read.parts, read.facts, window.first, window.objectsBefore, options);
  if (!objects) return false;
  read.objectsSeen = *objects;
  read.lines = 0;
  for (std::uint32_t n : read.partLines) read.lines += n;
  return true;
}

ReadResult parseSceneFile(std::string_view text, std::string fileName, const ReadOptions& options) {
  unsigned threads = options.threads > 0 ? options.threads : std::thread::hardware_concurrency();
  // A part of 1 MiB at least: the threads cost more than they save below.
  unsigned parts =
      static_cast<unsigned>(std::min<std::size_t>(std::max(threads, 1u), text.size() >> 20));
  if (text.size() >= kMinBytesInParts && parts > 1) {
    if (std::optional<ReadResult> read = parseSceneFileInParts(text, fileName, options, parts)) {
      return std::move(*read);
    }
  }
  ReadResult result{Scene{}, DiagnosticList(std::move(fileName), options.errorLimit)};
  SceneFileParser(text, options, result).run();
  return result;
}

}  // namespace scene
