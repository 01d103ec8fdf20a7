#include "tools/sfrender/render_hint.h"

#include <charconv>

#include "tools/common/diagnostic_printer.h"

namespace tools {

namespace {

// The remedy's value as a number, if it is one.
std::optional<double> valueOf(const scene::Remedy& remedy) {
  double value = 0;
  const char* end = remedy.value.data() + remedy.value.size();
  auto [stop, error] = std::from_chars(remedy.value.data(), end, value);
  if (error != std::errc() || stop != end) return std::nullopt;
  return value;
}

}  // namespace

bool remedyInUse(const scene::Remedy& remedy, const render::RenderSettings& settings) {
  std::optional<double> value = valueOf(remedy);
  if (!value) return false;
  switch (remedy.setting) {
    case scene::Setting::FieldOfView:
      return *value == settings.verticalFovDegrees;
    case scene::Setting::Width:
      return *value == settings.width;
    case scene::Setting::Height:
      return *value == settings.height;
    default:
      return false;
  }
}

std::string renderHintText(const scene::Diagnostic& d, const render::RenderSettings& settings) {
  // The hint with each "{N}" of a remedy in use left out (with the blank
  // before it), and the others numbered again.
  scene::Diagnostic shown = d;
  shown.hint.clear();
  shown.remedies.clear();
  bool named = false;
  for (std::size_t i = 0; i < d.hint.size(); ++i) {
    std::size_t n = i + 2 < d.hint.size() && d.hint[i] == '{' && d.hint[i + 2] == '}'
                        ? static_cast<std::size_t>(d.hint[i + 1] - '0')
                        : d.remedies.size();
    if (n >= d.remedies.size()) {
      shown.hint += d.hint[i];
      continue;
    }
    named = true;
    i += 2;
    if (remedyInUse(d.remedies[n], settings)) {
      if (!shown.hint.empty() && shown.hint.back() == ' ') shown.hint.pop_back();
      continue;
    }
    shown.hint += "{" + std::to_string(shown.remedies.size()) + "}";
    shown.remedies.push_back(d.remedies[n]);
  }
  if (named && shown.remedies.empty()) return {};
  return hintText(shown);
}

}  // namespace tools
