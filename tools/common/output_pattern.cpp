#include "tools/common/output_pattern.h"

#include <filesystem>
#include <map>

#include "tools/common/printable_text.h"
#include "tools/common/tool_streams.h"

namespace tools {

namespace {

constexpr const char* kPlaceholders[] = {"{stem}", "{name}", "{dir}"};

std::string placeholderValue(const std::string& placeholder, const std::string& input) {
  std::filesystem::path path(input);
  if (placeholder == "{stem}") return path.stem().string();
  if (placeholder == "{name}") return path.filename().string();
  std::string folder = path.parent_path().string();
  return folder.empty() ? "." : folder;
}

}  // namespace

bool hasPlaceholder(const std::string& pattern) {
  for (const char* placeholder : kPlaceholders) {
    if (pattern.find(placeholder) != std::string::npos) return true;
  }
  return false;
}

std::optional<std::string> expandOutputPattern(const std::string& pattern, const std::string& input,
                                               std::string& error) {
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
      error =
          "-o: '" + printableText(placeholder) + "' is no placeholder; use {stem}, {name} or {dir}";
      return std::nullopt;
    }
    out += pattern.substr(at, open - at) + placeholderValue(placeholder, input);
    at = close + 1;
  }
  return out + pattern.substr(std::min(at, pattern.size()));
}

std::optional<std::vector<std::string>> batchOutputs(const std::string& pattern,
                                                     const std::vector<std::string>& inputs,
                                                     std::string& error) {
  if (!inputs.empty() && !expandOutputPattern(pattern, inputs.front(), error)) return std::nullopt;
  if (inputs.size() > 1 && !hasPlaceholder(pattern)) {
    error = "-o '" + printableText(pattern) + "' names one file for " +
            std::to_string(inputs.size()) + " inputs; give a pattern such as 'out/{stem}.png'";
    return std::nullopt;
  }
  std::vector<std::string> outputs;
  std::map<std::string, std::string> inputOf;
  for (const std::string& input : inputs) {
    if (inputs.size() > 1 && isStandardStream(input)) {
      error = "standard input (-) cannot be one of several inputs";
      return std::nullopt;
    }
    std::optional<std::string> output = expandOutputPattern(pattern, input, error);
    if (!output) return std::nullopt;
    auto [earlier, added] = inputOf.emplace(*output, input);
    if (!added) {
      error = "'" + printableText(earlier->second) + "' and '" + printableText(input) +
              "' would both write '" + printableText(*output) + "'; use {dir} or {name} in -o";
      return std::nullopt;
    }
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
