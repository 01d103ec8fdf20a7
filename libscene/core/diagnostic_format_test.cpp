// The three forms of diagnostics, and which severities each shows.
#include "scenefile/diagnostic_format.h"

#include <gtest/gtest.h>

namespace scene {
namespace {

DiagnosticList sample() {
  DiagnosticList list("a.sf");
  Diagnostic& e = list.error(DiagnosticCode::InvalidNumber, {2, 5, 3}, "'nan' is not a number");
  e.notes.push_back({{1, 1, 6}, "block opened here"});
  Diagnostic& w = list.warning(DiagnosticCode::FileTooLarge, {}, "big");
  w.hint = "raise the limit with {0}";
  w.remedies = {{Setting::MaxFileSize, "9"}};
  list.note(DiagnosticCode::MissingCamera, {9, 1, 0}, "a note");
  return list;
}

TEST(DiagnosticFormat, TextQuotesTheSourceAndShortDoesNot) {
  DiagnosticList list = sample();
  SourceExcerpts quotes;
  quotes.capture("a.sf", "CAMERA\n0 0 nan\n", list);
  EXPECT_EQ(formatDiagnostics(list, {}, &quotes),
            "a.sf:2:5: error: 'nan' is not a number [invalid-number]\n"
            "    2 | 0 0 nan\n"
            "      |     ^~~\n"
            "a.sf:1:1: note: block opened here\n"
            "    1 | CAMERA\n"
            "      | ^~~~~~\n"
            "a.sf: warning: big [file-too-large]\n"
            "  hint: raise the limit with max-file-size=9\n"
            "a.sf:9:1: note: a note [missing-camera]\n");
  DiagnosticFormOptions brief;
  brief.form = DiagnosticForm::Short;
  brief.lowestSeverity = Severity::Warning;
  brief.warningsAsErrors = true;
  EXPECT_EQ(formatDiagnostics(list, brief, &quotes),
            "a.sf:2:5: error: 'nan' is not a number [invalid-number]\n"
            "a.sf:1:1: note: block opened here\n"
            "a.sf: error: big [file-too-large]\n"
            "  hint: raise the limit with max-file-size=9\n");
}

TEST(DiagnosticFormat, JsonIsAnArrayWithTheHintInTheCallersWords) {
  DiagnosticList list = sample();
  DiagnosticFormOptions json;
  json.form = DiagnosticForm::Json;
  json.lowestSeverity = Severity::Warning;
  json.hint = [](const Diagnostic& d) {
    return hintText(d.hint, d.remedies, [](const Remedy&) { return "max_file_size"; });
  };
  std::string text = formatDiagnostics(list, json);
  EXPECT_EQ(text.substr(0, 2), "[\n");
  EXPECT_NE(text.find("\"hint\": \"raise the limit with max_file_size\""), std::string::npos);
  EXPECT_NE(text.find("\"endColumn\": 8"), std::string::npos);
  EXPECT_EQ(text.find("a note"), std::string::npos);
  EXPECT_EQ(formatDiagnostics(DiagnosticList("x"), json), "[]\n");
}

TEST(DiagnosticFormat, FormsHaveTheToolsNames) {
  EXPECT_EQ(diagnosticFormFromName("short"), DiagnosticForm::Short);
  EXPECT_EQ(diagnosticFormFromName("json"), DiagnosticForm::Json);
  EXPECT_EQ(diagnosticFormFromName("Text"), std::nullopt);
}

}  // namespace
}  // namespace scene
