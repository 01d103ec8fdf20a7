#include "tools/common/output_pattern.h"

#include <algorithm>
#include <filesystem>

#include "tools/common/diagnostic_printer.h"
#include "tools/common/tool_streams.h"

namespace tools {

namespace {

constexpr const char* kPlaceholders[] = {"{stem}", "{name}", "{dir}"};

// A value that would be a path step of its own, or none, where a file
// name is meant.
bool isFileName(const std::string& value) {
  return !value.empty() && value != "." && value != ".." &&
         value.find_first_of(std::string("/\0", 2)) == std::string::npos;
}

bool climbs(const std::filesystem::path& folder) {
  return std::any_of(folder.begin(), folder.end(), [](const auto& part) { return part == ".."; });
}

// A pattern or a set of inputs the command line cannot have.
ToolFailure usageFailure(std::string message) {
  return toolFailure(ExitCode::Usage, std::move(message));
}

// The value of `placeholder` for `input`.
// `leading`: the placeholder begins the pattern, which has no fixed folder.
Outcome<std::string> placeholderValue(const std::string& placeholder, const std::string& input,
                                      bool leading) {
  if (isStandardStream(input)) {
    return usageFailure("-o: standard input has no name to put in " + placeholder +
                        "; name the output without a placeholder");
  }
  std::filesystem::path path(input);
  if (placeholder == "{dir}") {
    std::filesystem::path folder = path.parent_path();
    if (!leading && climbs(folder)) {
      return usageFailure(
          "-o: {dir} of '" + printableText(input) + "' is '" + printableText(folder.string()) +
          "': after the pattern's own folder, {dir} may not hold '..', which could climb out "
          "of it; start the pattern with {dir} to write beside the input");
    }
    return folder.empty() ? std::string(".") : folder.string();
  }
  std::string value = placeholder == "{stem}" ? path.stem().string() : path.filename().string();
  if (!isFileName(value)) {
    return usageFailure(
        "-o: " + placeholder + " of '" + printableText(input) + "' would be '" +
        printableText(value) +
        "', which is no file name (a placeholder never expands to nothing, '.' or '..'); "
        "rename the input or use another placeholder");
  }
  return value;
}

}  // namespace

bool hasPlaceholder(const std::string& pattern) {
  for (const char* placeholder : kPlaceholders) {
    if (pattern.find(placeholder) != std::string::npos) return true;
  }
  return false;
}

Outcome<std::string> expandOutputPattern(const std::string& pattern, const std::string& input) {
  std::string out;
  std::size_t at = 0;
  while (at < pattern.size()) {
    std::size_t open = pattern.find('{', at);
    if (open == std::string::npos) break;
    std::size_t close = pattern.find('}', open);
    std::string placeholder =
        pattern.substr(open, close == std::string::npos ? std::string::npos : close - open + 1);
    bool known = false;
    for (const char* name : kPlaceholders) known = known || placeholder == name;
    if (!known) {
      return usageFailure("-o: '" + printableText(placeholder) +
                          "' is no placeholder; use {stem}, {name} or {dir}");
    }
    Outcome<std::string> value = placeholderValue(placeholder, input, open == 0);
    if (!value) return value;
    out += pattern.substr(at, open - at) + *value;
    at = close + 1;
  }
  return out + pattern.substr(std::min(at, pattern.size()));
}

MaybeFailure batchInputsRefusal(const std::vector<std::string>& inputs) {
  if (inputs.size() > 1 && std::any_of(inputs.begin(), inputs.end(), isStandardStream)) {
    return usageFailure("standard input (-) cannot be one of several inputs");
  }
  return std::nullopt;
}

Outcome<std::vector<std::string>> batchOutputs(const std::string& pattern,
                                               const std::vector<std::string>& inputs) {
  if (MaybeFailure refusal = batchInputsRefusal(inputs)) return *refusal;
  if (!inputs.empty()) {
    if (MaybeFailure failure = expandOutputPattern(pattern, inputs.front()).maybeFailure()) {
      return *failure;
    }
  }
  if (inputs.size() > 1 && !hasPlaceholder(pattern)) {
    return usageFailure("-o '" + printableText(pattern) + "' names one file for " +
                        std::to_string(inputs.size()) +
                        " inputs; give a pattern such as 'out/{stem}.png'");
  }
  std::vector<std::string> outputs;
  for (const std::string& input : inputs) {
    Outcome<std::string> output = expandOutputPattern(pattern, input);
    if (!output) return output.failure();
    outputs.push_back(*output);
  }
  return outputs;
}

std::string batchSummary(const std::string& tool, int succeeded, int total,
                         const std::string& done) {
  return tool + ": " + std::to_string(succeeded) + " of " + std::to_string(total) + " " + done +
         ", " + std::to_string(total - succeeded) + " failed";
}

}  // namespace tools
