// Reading a scene in any format, through the format registry.
#include "scenefile/read.h"

#include "libscene/core/finite_check.h"
#include "libscene/text/text_lines.h"
#include "scenefile/validation.h"

namespace scene {

std::optional<Format> detectFormat(std::string_view text, std::string_view fileName) {
  // The strongest claim wins, and among equal claims the first row; the
  // extension decides only what the content leaves open.
  const FormatInfo* likely = nullptr;
  const FormatInfo* fallback = nullptr;
  for (const FormatInfo& row : formats()) {
    switch (row.recognise(text)) {
      case Recognition::Certain:
        return row.format;
      case Recognition::Likely:
        if (!likely) likely = &row;
        break;
      case Recognition::Default:
        if (!fallback) fallback = &row;
        break;
      case Recognition::None:
        break;
    }
  }
  if (likely) return likely->format;
  const FormatInfo* named = findFormatByExtension(fileName);
  if (named && named->readsUnrecognisedByExtension) return named->format;
  if (fallback) return fallback->format;
  return std::nullopt;
}

bool checkFileSize(std::uint64_t bytes, const ReadOptions& options, DiagnosticList& out,
                   std::string_view subject, bool sizeKnown) {
  if (bytes <= options.maxFileSize) return true;
  std::string limit = std::to_string(options.maxFileSize);
  Diagnostic& d =
      out.error(DiagnosticCode::FileTooLarge, {},
                std::string(subject) + " is " +
                    (sizeKnown ? std::to_string(bytes) + " bytes, more than the limit of " + limit
                               : "more than the limit of " + limit + " bytes"));
  d.hint = "raise the limit with {0} if the file is meant to be this large";
  d.remedies = {{Setting::MaxFileSize, sizeKnown ? std::to_string(bytes) : ""}};
  return false;
}

namespace {

// unknown-format, at the first word: what each format starts with, from the
// registry, so that the message names every format there is.
ReadResult unknownFormat(std::string_view text, std::string fileName, const ReadOptions& options) {
  ReadResult result{Scene{}, DiagnosticList(std::move(fileName), options.errorLimit)};
  LineCursor cursor(text);
  SourceSpan where{1, 1, 0};
  while (cursor.next()) {
    if (!cursor.blank()) {
      where = cursor.tokenSpan(0);
      break;
    }
  }
  std::span<const FormatInfo> rows = formats();
  std::string message = "not ";
  std::string hint;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const char* separator = i == 0 ? "" : i + 1 == rows.size() ? " or " : ", ";
    message += separator + std::string(rows[i].singular);
    hint += (i == 0 ? "" : ", ") + std::string(rows[i].singular) +
            (i == 0 ? " starts with " : " with ") + std::string(rows[i].startsWith);
  }
  result.diagnostics.error(DiagnosticCode::UnknownFormat, where, message).hint = hint;
  return result;
}

// The reader's result, with the last line of defence: the readers report a
// value that is not finite where it was made, and this makes sure that no
// accepted scene holds one, whatever a reader missed. The objects' test runs
// first on the reader's threads; only where it fails (or a thread could not
// start) does the check in order run, for its reports.
ReadResult checked(ReadResult result, const ReadOptions& options) {
  if (!result.ok()) return result;
  checkFramingFinite(result.scene, result.diagnostics);
  if (!objectsFinite(result.scene.objects, options.threads)) {
    checkObjectsFinite(result.scene.objects, result.diagnostics);
  }
  return result;
}

// file-too-large for a text over the limit, else nothing: the one check of
// both ways in.
std::optional<ReadResult> refusedAsTooLarge(std::string_view text, std::string& fileName,
                                            const ReadOptions& options) {
  ReadResult refused{Scene{}, DiagnosticList(fileName, options.errorLimit)};
  if (checkFileSize(text.size(), options, refused.diagnostics)) return std::nullopt;
  return refused;
}

ReadResult readAs(Format format, std::string_view text, std::string fileName,
                  const ReadOptions& options) {
  return checked(formatInfo(format).read(text, std::move(fileName), options), options);
}

}  // namespace

ReadResult parseScene(std::string_view text, std::string fileName, const ReadOptions& options) {
  if (auto refused = refusedAsTooLarge(text, fileName, options)) return std::move(*refused);
  std::optional<Format> format = detectFormat(text, fileName);
  if (!format) return unknownFormat(text, std::move(fileName), options);
  return readAs(*format, text, std::move(fileName), options);
}

ReadResult parseSceneAs(Format format, std::string_view text, std::string fileName,
                        const ReadOptions& options) {
  if (auto refused = refusedAsTooLarge(text, fileName, options)) return std::move(*refused);
  return readAs(format, text, std::move(fileName), options);
}

}  // namespace scene
