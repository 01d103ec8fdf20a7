#include "tools/sfbuild/scene_files.h"

#include <optional>

#include "scenefile/convert.h"
#include "scenefile/diagnostic.h"
#include "scenefile/format.h"
#include "scenefile/read.h"
#include "scenefile/validation.h"

namespace sfbuild {
namespace {

// "file:line:column: message", or "file: message" without a place.
std::string located(const scene::Diagnostic& d) {
  std::string where = d.file;
  if (d.span.known()) {
    where += ":" + std::to_string(d.span.line) + ":" + std::to_string(d.span.column);
  }
  return where + ": " + d.message;
}

std::string writableExtensions() {
  std::string list;
  for (const scene::FormatInfo& info : scene::formats()) {
    if (!info.write || info.extensions.empty()) continue;
    if (!list.empty()) list += ", ";
    list += std::string(info.extensions.front());
  }
  return list;
}

}  // namespace

bool saveSceneAs(BuilderState& state, const std::string& name, const FileSystem& files) {
  ++state.saveAttempts;
  const scene::FormatInfo* format = scene::findFormatByExtension(name);
  if (name.empty() || !format || !format->write) {
    state.lastSave = "could not save '" + name + "': the extension names no format (" +
                     writableExtensions() + ")";
    return false;
  }
  if (name != state.currentFile && files.exists(name)) {
    state.lastSave = "could not save " + name + ": it exists; sfbuild writes over no other file";
    return false;
  }
  // The registry's writer, as sfconvert: what the format cannot hold (a
  // scene file has no materials) is left out, as P always did.
  scene::DiagnosticList losses;
  // An instruction file's OUTPUT_FILE, where the scene has none, is named
  // after the file, as sfconvert names it.
  scene::ConversionOptions options;
  options.instructions.outputFile = scene::outputFileNameFor(name);
  std::optional<std::string> text =
      scene::convertScene(state.scene, format->format, options, losses);
  if (!text) {
    state.lastSave = "could not save " + name + ": the scene holds a value that is not finite";
    return false;
  }
  if (tools::MaybeFailure failure = files.write(name, *text)) {
    state.lastSave = "could not save " + name + ": " + failure->message;
    return false;
  }
  state.currentFile = name;
  state.lastSave = "saved " + name;
  return true;
}

bool openSceneFile(BuilderState& state, const std::string& name, const FileSystem& files) {
  tools::Outcome<std::string> text = files.read(name);
  if (!text) {
    state.lastSave = "could not open " + name + ": " + text.failure().message;
    return false;
  }
  scene::ReadResult result = scene::parseScene(*text, name);
  if (!result.ok()) {
    for (const scene::Diagnostic& d : result.diagnostics.items()) {
      if (d.severity != scene::Severity::Error) continue;
      state.lastSave = "could not open " + located(d);
      return false;
    }
  }
  // A transform under way belongs to the scene being left.
  handleKey(state, kKeyEscape, files);
  state.scene = std::move(result.scene);
  state.selection.reset();
  recordChange(state);
  state.currentFile = name;
  state.lastSave = "opened " + name;
  return true;
}

}  // namespace sfbuild
