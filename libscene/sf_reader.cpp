#include "libscene/sf_reader.h"

#include <algorithm>
#include <array>
#include <optional>

#include "libscene/reader_support.h"
#include "libscene/text_lines.h"
#include "libscene/validation.h"

namespace scene {

namespace {

constexpr std::array<std::string_view, 6> kRecordNames = {"CAMERA", "LIGHT",    "PLANE",
                                                          "SPHERE", "CYLINDER", "CUBE"};
constexpr std::string_view kExpectedRecord =
    "a record name (CAMERA, LIGHT, PLANE, SPHERE, CYLINDER or CUBE)";

enum class RecordKind { Camera, Light, Plane, Sphere, Cylinder, Cube, Unknown };

RecordKind recordKindFromName(std::string_view name) {
  for (std::size_t i = 0; i < kRecordNames.size(); ++i) {
    if (kRecordNames[i] == name) return static_cast<RecordKind>(i);
  }
  return RecordKind::Unknown;
}

ObjectKind objectKindOf(RecordKind kind) {
  switch (kind) {
    case RecordKind::Plane:
      return ObjectKind::Plane;
    case RecordKind::Sphere:
      return ObjectKind::Sphere;
    case RecordKind::Cylinder:
      return ObjectKind::Cylinder;
    default:
      return ObjectKind::Cube;
  }
}

bool startsLikeNumber(std::string_view token) {
  char c = token.front();
  return (c >= '0' && c <= '9') || c == '.' || c == '+' || c == '-';
}

// Upper bound on the records a text can hold, for one allocation up front:
// every record starts with a line that starts with a letter. Capped so that
// a hostile count costs no more than a growing vector would.
std::size_t estimateRecords(std::string_view text) {
  std::size_t count = 0;
  char previous = '\n';
  for (char c : text) {
    if (previous == '\n' && c >= 'A' && c <= 'Z') ++count;
    previous = c;
  }
  return std::min<std::size_t>(count, std::size_t{1} << 22);
}

class SceneFileParser {
 public:
  SceneFileParser(std::string_view text, const ReadOptions& options, ReadResult& result)
      : cursor_(text), options_(options), scene_(result.scene), out_(result.diagnostics) {
    scene_.objects.reserve(estimateRecords(text));
  }

  void run() {
    while (!out_.full() && pull()) {
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
    finish();
  }

 private:
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
                     "expected " + std::string(kExpectedRecord) + ", found a number")
              .hint = "each record is a name line, a colour line and four matrix rows";
        }
        resyncing_ = true;
        return;
      }
      reportUnknownKeyword(cursor_, 0, kRecordNames, kExpectedRecord, out_);
      // "sphere" is still a sphere for the rest of the checks.
      if (auto guess = suggestKeyword(name, kRecordNames);
          guess && guess->size() == name.size()) {
        kind = recordKindFromName(*guess);
      }
    }
    resyncing_ = false;
    if (cursor_.tokenCount() > 1) {
      out_.error(DiagnosticCode::TokenCount, cursor_.tokenSpan(1),
                 "a record name stands alone on its line");
    }
    noteRecordOrder(kind, nameSpan);
    readBody(kind, name, nameSpan, false);
  }

  // The colour line and the four matrix rows of a record whose name line is
  // the cursor's; `damaged` when that line was unreadable, and then a record
  // cut short goes unreported (the damage is the error).
  void readBody(RecordKind kind, std::string_view name, SourceSpan nameSpan, bool damaged) {
    RecordSpans spans;
    spans.record = nameSpan;
    std::array<double, 3> colour{};
    std::array<double, 16> rows{};
    bool valuesOk = true;
    bool blankReported = false;
    int linesRead = 0;
    while (linesRead < 5) {
      if (!cursor_.next()) {
        if (!damaged) reportTruncated(name, nameSpan, linesRead, "the file ends");
        return;
      }
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
      if (linesRead == 1) {
        valuesOk &= readNumbers(cursor_, 0, 3, colour.data(), "the colour line", out_);
        for (int i = 0; i < 3 && i < static_cast<int>(cursor_.storedTokens()); ++i) {
          spans.colour[i] = cursor_.tokenSpan(i);
        }
      } else {
        int row = linesRead - 2;
        static constexpr std::string_view kRowNames[] = {"matrix row 1", "matrix row 2",
                                                         "matrix row 3", "matrix row 4"};
        valuesOk &= readNumbers(cursor_, 0, 4, rows.data() + 4 * row, kRowNames[row], out_);
        for (int c = 0; c < 4 && c < static_cast<int>(cursor_.storedTokens()); ++c) {
          // Spans are kept by matrix position, which a transposed file swaps.
          int r = row;
          int col = c;
          if (options_.transposedMatrices) std::swap(r, col);
          spans.matrix[r * 4 + col] = cursor_.tokenSpan(c);
        }
      }
    }
    if (!valuesOk || kind == RecordKind::Unknown) return;

    glm::dmat4 matrix;
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        // GLM is column-major (matrix[c][r]); the file is row by row.
        double value = rows[r * 4 + c];
        if (options_.transposedMatrices) {
          matrix[r][c] = value;
        } else {
          matrix[c][r] = value;
        }
      }
    }
    glm::dvec3 rgb(colour[0], colour[1], colour[2]);
    addRecord(kind, rgb, matrix, spans);
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
        scene_.objects.push_back(std::move(object));
        return;
      }
    }
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
    if (out_.full()) return;
    if (!firstRecord_) {
      out_.error(DiagnosticCode::MissingCamera, SourceSpan{1, 1, 0},
                 out_.hasErrors() ? "scene has no CAMERA record" : "file holds no records")
          .hint = "a scene file starts with a CAMERA record, an instruction file with OUTPUT_FILE";
      return;
    }
    if (!cameraSpan_) {
      out_.error(DiagnosticCode::MissingCamera, *firstRecord_, "scene has no CAMERA record")
          .hint = "the first record of a scene file must be the CAMERA";
    } else if (!firstIsCamera_) {
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
  std::optional<SourceSpan> firstRecord_;
  bool firstIsCamera_ = false;
  std::string firstName_;
  std::optional<SourceSpan> cameraSpan_;
};

}  // namespace

ReadResult parseSceneFile(std::string_view text, std::string fileName, const ReadOptions& options) {
  ReadResult result{Scene{}, DiagnosticList(std::move(fileName), options.errorLimit)};
  SceneFileParser(text, options, result).run();
  return result;
}

}  // namespace scene
