#include "tools/common/output_plan.h"

#include <sys/stat.h>

#include <map>
#include <system_error>

#include "tools/common/output_location.h"
#include "tools/common/diagnostic_printer.h"
#include "tools/common/tool_streams.h"

namespace tools {

namespace fs = std::filesystem;

FileIdentity fileIdentity(const fs::path& path) {
  std::error_code ec;
  // followLinks resolves the folders' links and the last component's chain,
  // as the kernel does for open() and StagedFile for a write. A chain that
  // never ends is compared by its spelling: neither read nor write gets
  // through it.
  fs::path end = scene::followLinks(path).value_or(fs::absolute(path, ec).lexically_normal());
  struct stat info {};
  if (::stat(end.c_str(), &info) == 0) return {info.st_dev, info.st_ino, {}};
  // Not there yet: the nearest folder that is, which a folder's link, `.`
  // or `..` cannot disguise, and the names below it.
  std::string below = end.filename().string();
  for (fs::path folder = end.parent_path(); !folder.empty(); folder = folder.parent_path()) {
    if (::stat(folder.c_str(), &info) == 0) {
      return {info.st_dev, info.st_ino, fs::path(below).lexically_normal().string()};
    }
    if (folder == folder.parent_path()) break;
    below = folder.filename().string() + "/" + below;
  }
  return {0, 0, end.string()};
}

void OutputPlan::addInput(const std::string& path) {
  if (!isStandardStream(path)) inputs_.push_back(path);
}

void OutputPlan::addOutput(const std::string& path, const std::string& from,
                           const std::string& role) {
  if (!isStandardStream(path)) outputs_.push_back({path, from, role});
}

std::optional<OutputClash> OutputPlan::firstClash() const {
  std::map<FileIdentity, std::size_t> inputs;
  for (std::size_t i = 0; i < inputs_.size(); ++i) inputs.emplace(fileIdentity(inputs_[i]), i);
  std::map<FileIdentity, std::size_t> outputs;
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    FileIdentity identity = fileIdentity(outputs_[i].path);
    if (auto input = inputs.find(identity); input != inputs.end()) {
      return OutputClash{true, i, input->second};
    }
    auto [earlier, added] = outputs.emplace(identity, i);
    if (!added) return OutputClash{false, i, earlier->second};
  }
  return std::nullopt;
}

std::string OutputPlan::wouldWrite(const Output& output) const {
  std::string text =
      "'" + printableText(output.from) + "' would write '" + printableText(output.path) + "'";
  return output.role.empty() ? text : text + " (" + output.role + ")";
}

std::string OutputPlan::describe(const OutputClash& clash) const {
  const Output& output = outputs_[clash.output];
  if (clash.overInput) {
    return wouldWrite(output) + ", which is the input '" + printableText(inputs_[clash.other]) +
           "'";
  }
  const Output& earlier = outputs_[clash.other];
  if (earlier.path == output.path && earlier.role.empty() && output.role.empty()) {
    return "'" + printableText(earlier.from) + "' and '" + printableText(output.from) +
           "' would both write '" + printableText(output.path) + "'";
  }
  return wouldWrite(earlier) + " and " + wouldWrite(output) +
         (earlier.path == output.path ? "" : ", which is the same file");
}

bool writesOverInput(const std::string& input, const std::string& output) {
  if (input.empty()) return false;
  OutputPlan plan;
  plan.addInput(input);
  plan.addOutput(output, input);
  return plan.firstClash().has_value();
}

}  // namespace tools
