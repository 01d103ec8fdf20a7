/// @file
/// Diagnostics: what the library reports about an input, as values.
///
/// The library collects diagnostics and never prints or exits; the tools decide
/// how to show them (text in the compiler's form, or JSON). Every kind of
/// problem has a stable code, listed in one table in docs/DIAGNOSTICS.md.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace scene {

enum class Severity : std::uint8_t { Note, Warning, Error };

std::string_view severityName(Severity severity);

/// A place in a source file. Lines and columns count from 1; columns count
/// bytes. A span of length 0 points between two characters (the end of a line).
struct SourceSpan {
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  std::uint32_t length = 0;

  bool known() const { return line != 0; }
  friend bool operator==(const SourceSpan&, const SourceSpan&) = default;
};

/// A stable code for each kind of problem, printed by its name (codeName).
/// The codes are listed once, in diagnostic_codes.def, and documented in
/// docs/DIAGNOSTICS.md; new ones are appended there, so that no value
/// changes, and a renamed one keeps its old name as an alias.
enum class DiagnosticCode : std::uint16_t {
#define SCENEFILE_DIAGNOSTIC(enumerator, name) enumerator,
#include "scenefile/diagnostic_codes.def"
};

/// Every code, in declaration order: for documentation and coverage tests.
const std::vector<DiagnosticCode>& allDiagnosticCodes();

/// The stable kebab-case name of a code, as printed in brackets; "unknown"
/// for a value that is no code.
std::string_view codeName(DiagnosticCode code);

/// The code with the name `name` as codeName prints it, or as it was before
/// a rename (docs/DIAGNOSTICS.md, "Renamed codes"), so that a filter written
/// for an older version still finds it; nothing for any other text. Exact
/// and case-sensitive.
std::optional<DiagnosticCode> diagnosticCodeFromName(std::string_view name);

/// A replacement the user (or an editor) can apply to fix the problem.
struct FixIt {
  SourceSpan span;
  std::string replacement;
  friend bool operator==(const FixIt&, const FixIt&) = default;
};

/// A secondary location that explains a diagnostic ("block opened here").
struct DiagnosticNote {
  SourceSpan span;
  std::string message;
  friend bool operator==(const DiagnosticNote&, const DiagnosticNote&) = default;
};

struct Diagnostic {
  Severity severity = Severity::Error;
  DiagnosticCode code = DiagnosticCode::UnknownFormat;
  std::string file;
  SourceSpan span;
  /// Lower case, no final period, as in clang.
  std::string message;
  /// One line of advice printed after the message, or empty.
  std::string hint;
  std::vector<DiagnosticNote> notes;
  std::optional<FixIt> fixIt;

  friend bool operator==(const Diagnostic&, const Diagnostic&) = default;
};

/// Collects the diagnostics of one operation, in the order they were found.
/// After `errorLimit` errors the list takes no more and says so once, so that a
/// file of garbage costs bounded memory; readers stop when `full()`.
class DiagnosticList {
 public:
  static constexpr std::size_t kDefaultErrorLimit = 1000;

  explicit DiagnosticList(std::string file = {}, std::size_t errorLimit = kDefaultErrorLimit)
      : file_(std::move(file)), errorLimit_(errorLimit) {}

  const std::string& file() const { return file_; }

  Diagnostic& report(Severity severity, DiagnosticCode code, SourceSpan span, std::string message);
  Diagnostic& error(DiagnosticCode code, SourceSpan span, std::string message) {
    return report(Severity::Error, code, span, std::move(message));
  }
  Diagnostic& warning(DiagnosticCode code, SourceSpan span, std::string message) {
    return report(Severity::Warning, code, span, std::move(message));
  }
  Diagnostic& note(DiagnosticCode code, SourceSpan span, std::string message) {
    return report(Severity::Note, code, span, std::move(message));
  }

  void append(const DiagnosticList& other);

  bool full() const { return errorCount_ >= errorLimit_; }
  bool hasErrors() const { return errorCount_ != 0; }
  std::size_t errorCount() const { return errorCount_; }
  std::size_t warningCount() const { return warningCount_; }
  const std::vector<Diagnostic>& items() const { return items_; }
  bool empty() const { return items_.empty(); }

 private:
  std::string file_;
  std::vector<Diagnostic> items_;
  std::size_t errorLimit_;
  std::size_t errorCount_ = 0;
  std::size_t warningCount_ = 0;
  Diagnostic discarded_;  // what report() returns once the list is full
};

}  // namespace scene
