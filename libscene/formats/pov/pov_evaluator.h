// The meaning of a POV-Ray scene's words: the directives (#version,
// #include, #declare, #undef, #default, and the loops and conditions it
// refuses to run), the names they declare, and the expressions over them
// (floats, vectors and colours, the built-in identifiers and functions),
// each evaluated as POV-Ray evaluates it. Every number an expression gives
// is finite, or an error at the operator that made it otherwise.
//
// A #declare of an object, a material or a transform, and #default's
// block, hold what the scene layer above reads: it supplies them through
// the hooks at the end.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "libscene/formats/pov/pov_scene_parts.h"
#include "libscene/formats/pov/pov_symbol.h"
#include "libscene/formats/pov/pov_token_stream.h"
#include "libscene/formats/pov/pov_value.h"

namespace scene {

class PovEvaluator : public PovTokenStream {
 protected:
  PovEvaluator(std::string_view text, const ReadOptions& options, DiagnosticList& out)
      : PovTokenStream(text, options, out) {}
  virtual ~PovEvaluator() = default;

  // --- Directives ----------------------------------------------------------

  // The directive token next, and what it takes.
  void directive();

  // --- Names ---------------------------------------------------------------

  // The symbol declared under `name`, or null.
  const PovSymbol* findSymbol(std::string_view name) const {
    auto it = symbols_.find(std::string(name));
    return it == symbols_.end() ? nullptr : &it->second;
  }
  bool isDeclared(std::string_view name) const { return symbols_.count(std::string(name)) != 0; }

  // Whether an undeclared name is most likely one of a standard include
  // file that was included but is not read: POV-Ray's keywords are lower
  // case, the include files' names are capitalised.
  bool fromOtherInclude(std::string_view name) const;
  // The first standard include file other than colors.inc, for a hint;
  // only when fromOtherInclude said so.
  const std::string& firstOtherInclude() const { return otherIncludes_.front(); }

  // An error for a name that is not declared (or a macro call, or a name
  // of an include file not read), with a did-you-mean.
  [[noreturn]] void unknownIdentifier(const PovToken& word);

  // --- Expressions ---------------------------------------------------------

  PovValue expression();
  // A colour where one is expected: `color` is optional.
  PovValue colour();
  // `red 1 green 0.5 filter 0.2 ...` after a colour.
  PovValue colourModifiers(PovValue value);
  // An expression that must be a vector (a float stands for one), or a
  // float; `what` names it in the error.
  glm::dvec3 vectorValue(std::string_view what);
  double floatValue(std::string_view what);
  // A float when one follows (keywords such as `metallic` take one or none).
  std::optional<double> optionalFloat();

  // Reports value-not-finite at `where` and abandons the statement when a
  // component is NaN or infinite; `what` says what made it.
  void requireFinite(const PovValue& value, SourceSpan where, const std::string& what);
  void requireFinite(const glm::dmat4& m, SourceSpan where, const std::string& what);
  void requireFinite(const glm::dvec3& v, SourceSpan where, const std::string& what);

  // --- What the scene layer reads for a directive ----------------------------

  // An object statement (its keyword next): #declare Name = sphere { ... }.
  virtual PovPendingObject objectStatement() = 0;
  // pigment, finish, texture, interior or material { ... } after `keyword`,
  // into `patch`.
  virtual void materialBlock(const PovToken& keyword, PovMaterialPatch& patch) = 0;
  // transform { ... }, its keyword taken.
  virtual PovTransform transformBlock() = 0;
  // #default { ... }, the directive taken.
  virtual void defaultsBlock() = 0;

 private:
  struct NestingGuard;

  void include();
  void declare(const PovToken& d);

  PovValue term();
  PovValue unary();
  PovValue primary();
  PovValue operation(const PovValue& a, const PovValue& b, PovOperator op, SourceSpan where);
  [[noreturn]] void notFinite(SourceSpan where, const std::string& what);
  std::optional<PovValue> builtIn(std::string_view w);
  PovValue functionCall(const PovToken& name);
  PovValue colourKeyword(const PovToken& word);
  PovValue colourAfterKeyword();

  int nesting_ = 0;
  std::unordered_map<std::string, PovSymbol> symbols_;
  bool coloursIncluded_ = false;
  std::vector<std::string> otherIncludes_;
};

}  // namespace scene
