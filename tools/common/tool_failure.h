// A failure on the tools' side as a value: the exit status it ends the run
// with and what the tool says of it. Each step that can fail returns one
// (nothing when it went ahead), and one place per tool prints it and turns
// it into the exit status (ToolOutput::report), as CLI11's errors carry
// theirs; no status is read back from a message's words.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>

#include "tools/common/exit_code.h"

namespace tools {

struct ToolFailure {
  ExitCode code = ExitCode::InvalidInput;
  // "TOOL: error: MESSAGE", or "FILE: error: MESSAGE" when `file` is set.
  // Empty when what went wrong is printed already: the input's diagnostics.
  std::string message;
  // "  hint: HINT" under the message, when not empty.
  std::string hint;
  // The file the message is about, named where the tool would be.
  std::string file;
};

// What a step that can fail returns: nothing when it went ahead.
using MaybeFailure = std::optional<ToolFailure>;

inline ToolFailure toolFailure(ExitCode code, std::string message, std::string hint = {}) {
  return ToolFailure{code, std::move(message), std::move(hint), {}};
}

inline ToolFailure fileFailure(ExitCode code, std::string file, std::string message) {
  return ToolFailure{code, std::move(message), {}, std::move(file)};
}

// A failure whose diagnostics are printed already: its exit status alone.
inline ToolFailure toldFailure(ExitCode code) {
  return ToolFailure{code, {}, {}, {}};
}

// What a step that makes a value returns: the value, or the failure that
// kept it from being made, never both (C++20 has no std::expected).
template <class T>
class Outcome {
 public:
  Outcome(T value) : result_(std::in_place_index<0>, std::move(value)) {}
  Outcome(ToolFailure failure) : result_(std::in_place_index<1>, std::move(failure)) {}

  bool ok() const { return result_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& operator*() { return std::get<0>(result_); }
  const T& operator*() const { return std::get<0>(result_); }
  T* operator->() { return &std::get<0>(result_); }
  const T* operator->() const { return &std::get<0>(result_); }
  T valueOr(T fallback) const { return ok() ? **this : std::move(fallback); }
  // Only when !ok().
  const ToolFailure& failure() const { return std::get<1>(result_); }
  // Nothing when ok(): for a step that passes a failure on.
  MaybeFailure maybeFailure() const { return ok() ? MaybeFailure() : MaybeFailure(failure()); }
  // Whether it holds `value`.
  friend bool operator==(const Outcome& outcome, const T& value) {
    return outcome.ok() && *outcome == value;
  }

 private:
  std::variant<T, ToolFailure> result_;
};

}  // namespace tools
