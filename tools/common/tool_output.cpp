#include "tools/common/tool_output.h"

#include <cstdio>


namespace tools {

std::string countOf(std::size_t n, std::string_view word) {
  return std::to_string(n) + " " + std::string(word) + (n == 1 ? "" : "s");
}

std::string sceneContents(const scene::Scene& scene) {
  return countOf(scene.objects.size(), "object") + ", " + countOf(scene.lights.size(), "light");
}

ToolOutput::ToolOutput(std::string tool, const ToolStreams& streams, const CommonFlags& flags)
    : tool_(std::move(tool)),
      streams_(streams),
      flags_(flags),
      style_(useColor(flags.colorMode(), streams.errIsTerminal, streams)) {}

void ToolOutput::error(std::string_view message, std::string_view hint) const {
  streams_.err << tool_ << ": " << style_.severity(scene::Severity::Error, "error:") << ' '
               << message << '\n';
  if (!hint.empty()) streams_.err << "  " << style_.location("hint:") << ' ' << hint << '\n';
}

void ToolOutput::fileError(std::string_view file, std::string_view message) const {
  streams_.err << printableText(file) << ": " << style_.severity(scene::Severity::Error, "error:")
               << ' ' << message << '\n';
}

int ToolOutput::report(const ToolFailure& failure) const {
  if (!failure.file.empty()) {
    fileError(failure.file, failure.message);
    // Unstyled, as under a file's error it has always printed.
    if (!failure.hint.empty()) streams_.err << "  hint: " << failure.hint << '\n';
  } else if (!failure.message.empty()) {
    error(failure.message, failure.hint);
  }
  return toInt(failure.code);
}

void ToolOutput::warning(std::string_view message) const {
  if (flags_.quiet) return;
  streams_.err << tool_ << ": " << style_.severity(scene::Severity::Warning, "warning:") << ' '
               << message << '\n';
}

void ToolOutput::info(std::string_view message) const {
  if (!flags_.quiet) streams_.err << tool_ << ": " << message << '\n';
}

void ToolOutput::detail(std::string_view message) const {
  if (flags_.verbose) streams_.err << tool_ << ": " << message << '\n';
}

void ToolOutput::step(std::string_view what) {
  auto now = std::chrono::steady_clock::now();
  if (flags_.verbose) {
    double seconds = std::chrono::duration<double>(now - stepStart_).count();
    char figure[32];
    std::snprintf(figure, sizeof figure, "%.3f", seconds);
    streams_.err << tool_ << ": " << what << " took " << figure << " s\n";
  }
  stepStart_ = now;
}

DiagnosticStyle ToolOutput::diagnosticStyle(DiagnosticFormat format, bool warningsAsErrors) const {
  DiagnosticStyle style;
  style.terminal = style_;
  style.quoteSource = format == DiagnosticFormat::Text;
  style.warningsAsErrors = warningsAsErrors;
  style.errorsOnly = flags_.quiet;
  // A clean run says what it wrote and what was lost; what was decided on
  // the way is asked for.
  style.notesShown = flags_.verbose;
  return style;
}

}  // namespace tools
