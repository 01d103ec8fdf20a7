#include "libscene/formats/pov/pov_evaluator.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "libscene/formats/pov/pov_keywords.h"
#include "libscene/formats/pov/pov_limits.h"
#include "libscene/formats/pov/pov_names.h"
#include "libscene/text/number.h"
#include "libscene/text/reader_support.h"

namespace scene {

// Counts the expressions open inside each other: past kMaxPovNesting
// reading stops [pov-limit], before the recursion can exhaust the stack.
struct PovEvaluator::NestingGuard {
  explicit NestingGuard(PovEvaluator& p, SourceSpan where) : parser(p) {
    if (++parser.nesting_ > kMaxPovNesting) {
      parser.out_.error(
          DiagnosticCode::PovLimit, where,
          "expressions nest more than " + std::to_string(kMaxPovNesting) + " deep: refused");
      throw PovStopReading{};
    }
  }
  ~NestingGuard() { --parser.nesting_; }
  PovEvaluator& parser;
};

// --- Directives --------------------------------------------------------------

void PovEvaluator::directive() {
  PovToken d = take();
  std::string_view name = d.text;
  if (name == "version") {
    expression();
    acceptSymbol(';');
    return;
  }
  if (name == "include") return include();
  if (name == "declare" || name == "local") return declare(d);
  if (name == "undef") {
    if (peek().kind == PovTokenKind::Word) symbols_.erase(std::string(take().text));
    return;
  }
  if (name == "default") return defaultsBlock();
  if (name == "fopen" || name == "read" || name == "write" || name == "fclose") {
    refuse(d.span, "'#" + std::string(name) + "' reads or writes files: refused",
           "this reader reads no file but the scene itself");
  }
  if (name == "if" || name == "ifdef" || name == "ifndef" || name == "switch" || name == "while" ||
      name == "for" || name == "macro") {
    unsupported(d.span, "'#" + std::string(name) + "'",
                "this reader runs no loop, macro or condition; {0} skips it to its #end");
    skipDirectiveBlock();
    return;
  }
  if (name == "debug" || name == "warning" || name == "error" || name == "render" ||
      name == "statistics") {
    ignored(d.span, "'#" + std::string(name) + "' is ignored");
    if (peek().kind == PovTokenKind::String) take();
    return;
  }
  if (name == "end" || name == "else" || name == "elseif" || name == "case" || name == "range" ||
      name == "break") {
    fail(d.span, "'#" + std::string(name) + "' without the directive it belongs to");
  }
  unsupported(d.span, "the directive '#" + std::string(name) + "'");
}

void PovEvaluator::include() {
  if (peek().kind != PovTokenKind::String) {
    fail(peek().span, "#include takes a file name in quotes");
  }
  PovToken name = take();
  if (!isPovStandardInclude(name.text)) {
    refuse(name.span,
           "'#include \"" + std::string(name.text.substr(0, 60)) +
               "\"' would read another file: refused",
           "only POV-Ray's standard include files (colors.inc, textures.inc, ...) may be "
           "included; this reader knows colors.inc's colours without reading it");
  }
  if (povIncludeDeclaresColours(name.text)) coloursIncluded_ = true;
  if (name.text != "colors.inc") otherIncludes_.push_back(std::string(name.text));
}

void PovEvaluator::declare(const PovToken& d) {
  if (peek().kind != PovTokenKind::Word) {
    fail(peek().span, "#" + std::string(d.text) + " takes a name, found " + describe(peek()));
  }
  PovToken name = take();
  expectSymbol('=', "after the name of #" + std::string(d.text));
  PovSymbol symbol;
  const PovToken& t = peek();
  std::string_view w = t.kind == PovTokenKind::Word ? t.text : std::string_view{};
  if (povObjectKind(w) || w == "object") {
    symbol.kind = PovSymbolKind::Object;
    symbol.object = std::make_shared<PovPendingObject>(objectStatement());
  } else if (w == "pigment" || w == "finish" || w == "texture" || w == "interior" ||
             w == "material") {
    PovToken keyword = take();
    symbol.kind = w == "pigment"    ? PovSymbolKind::Pigment
                  : w == "finish"   ? PovSymbolKind::Finish
                  : w == "texture"  ? PovSymbolKind::Texture
                  : w == "interior" ? PovSymbolKind::Interior
                                    : PovSymbolKind::Material;
    materialBlock(keyword, symbol.patch);
  } else if (w == "transform") {
    take();
    symbol.kind = PovSymbolKind::Transform;
    symbol.transform = transformBlock();
  } else if (t.kind == PovTokenKind::String || w == "camera" || w == "light_source" ||
             w == "normal" || isPovUnsupportedStatement(w)) {
    PovToken keyword = take();
    std::string what =
        keyword.kind == PovTokenKind::String ? "a string" : "'" + std::string(w) + "'";
    unsupported(keyword.span, "declaring " + what);
    skipBlockAfter();
    symbol.kind = PovSymbolKind::Other;
    symbol.what = what;
  } else {
    try {
      symbol.value = colourModifiers(expression());
    } catch (const PovParseError&) {
      symbol.failed = true;
      symbols_.insert_or_assign(std::string(name.text), std::move(symbol));
      throw;
    }
  }
  acceptSymbol(';');
  bool inserted = symbols_.insert_or_assign(std::string(name.text), std::move(symbol)).second;
  if (inserted && symbols_.size() > kMaxPovDeclarations) {
    out_.error(DiagnosticCode::PovLimit, name.span,
               "more than " + std::to_string(kMaxPovDeclarations) + " names are declared: refused");
    throw PovStopReading{};
  }
}

// --- Expressions -------------------------------------------------------------

PovValue PovEvaluator::expression() {
  PovValue value = term();
  for (;;) {
    SourceSpan where = peek().span;
    if (acceptSymbol('+')) {
      value = operation(value, term(), PovOperator::Add, where);
    } else if (acceptSymbol('-')) {
      value = operation(value, term(), PovOperator::Subtract, where);
    } else {
      return value;
    }
  }
}

PovValue PovEvaluator::term() {
  PovValue value = unary();
  for (;;) {
    SourceSpan where = peek().span;
    if (acceptSymbol('*')) {
      value = operation(value, unary(), PovOperator::Multiply, where);
    } else if (acceptSymbol('/')) {
      value = operation(value, unary(), PovOperator::Divide, where);
    } else {
      return value;
    }
  }
}

// a op b, refused at the operator when it is not finite (0 / 0, an
// overflow): POV-Ray would carry the NaN on, and nothing after could tell
// where it came from.
PovValue PovEvaluator::operation(const PovValue& a, const PovValue& b, PovOperator op,
                                 SourceSpan where) {
  PovValue value = applyOperator(a, b, op);
  static constexpr const char* kSymbols[] = {"+", "-", "*", "/"};
  const char* symbol = kSymbols[static_cast<int>(op)];
  if (a.isFloat() && b.isFloat()) {
    requireFinite(value, where, formatNumber(a.v[0]) + " " + symbol + " " + formatNumber(b.v[0]));
  } else {
    requireFinite(value, where,
                  std::string("'") + symbol + "' of " + std::string(a.typeName()) + " and " +
                      std::string(b.typeName()));
  }
  return value;
}

void PovEvaluator::requireFinite(const PovValue& value, SourceSpan where, const std::string& what) {
  for (int i = 0; i < value.size; ++i) {
    double x = value.v[i];
    if (std::isnan(x)) notFinite(where, what + " gives nan");
    if (std::isinf(x)) notFinite(where, what + " gives " + (x > 0 ? "inf" : "-inf"));
  }
}

void PovEvaluator::notFinite(SourceSpan where, const std::string& what) {
  out_.error(DiagnosticCode::ValueNotFinite, where, what + ", which is not a finite number").hint =
      "every number of a scene must be a finite double";
  throw PovParseError{};
}

// After a transformation or a shape is built from finite numbers, its
// matrix can still overflow (a scale by 1e200 twice).
void PovEvaluator::requireFinite(const glm::dmat4& m, SourceSpan where, const std::string& what) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      double x = m[c][r];
      if (!std::isfinite(x)) {
        notFinite(where, what + " makes a matrix entry " +
                             (std::isnan(x) ? "nan"
                              : x > 0       ? "inf"
                                            : "-inf"));
      }
    }
  }
}

void PovEvaluator::requireFinite(const glm::dvec3& v, SourceSpan where, const std::string& what) {
  requireFinite(PovValue::vector(v), where, what);
}

PovValue PovEvaluator::unary() {
  NestingGuard guard(*this, peek().span);
  if (acceptSymbol('-')) {
    PovValue v = unary();
    for (int i = 0; i < v.size; ++i) v.v[i] = -v.v[i];
    return v;
  }
  if (acceptSymbol('+')) return unary();
  if (peek().isSymbol('!')) {
    PovToken bang = take();
    PovValue v = unary();
    if (!v.isFloat()) fail(bang.span, "'!' takes a float");
    return PovValue::number(v.v[0] == 0.0 ? 1.0 : 0.0);
  }
  PovValue value = primary();
  // Dot access to a component: V.x, C.red.
  while (peek().isSymbol('.') && peek(1).kind == PovTokenKind::Word) {
    take();
    PovToken member = take();
    std::optional<double> part = povComponent(value, member.text);
    if (!part) {
      fail(member.span,
           std::string(value.typeName()) + " has no component '" + std::string(member.text) + "'");
    }
    value = PovValue::number(*part);
  }
  return value;
}

PovValue PovEvaluator::primary() {
  const PovToken& t = peek();
  if (t.kind == PovTokenKind::Number) return PovValue::number(take().number);
  if (t.isSymbol('(')) {
    take();
    PovValue v = expression();
    expectSymbol(')', "to close the parenthesis");
    return v;
  }
  if (t.isSymbol('<')) {
    PovToken open = take();
    std::vector<double> parts;
    for (;;) {
      PovValue v = expression();
      if (!v.isFloat()) fail(open.span, "a vector's components are floats");
      parts.push_back(v.v[0]);
      if (acceptSymbol(',')) continue;
      if (acceptSymbol('>')) break;
      fail(peek().span, "expected ',' or '>' in the vector, found " + describe(peek()));
    }
    if (parts.size() < 2 || parts.size() > 5) {
      fail(open.span, "a vector has 2 to 5 components, this one " + std::to_string(parts.size()));
    }
    return PovValue::vector(parts);
  }
  if (t.kind != PovTokenKind::Word) {
    fail(t.span, "expected a number, a vector or a colour, found " + describe(t));
  }
  PovToken word = take();
  std::string_view w = word.text;
  if (w == "rgb" || w == "rgbf" || w == "rgbt" || w == "rgbft" || w == "srgb" || w == "srgbf" ||
      w == "srgbt" || w == "srgbft") {
    return colourKeyword(word);
  }
  if (w == "color" || w == "colour") return colourModifiers(colourAfterKeyword());
  if (w == "red" || w == "green" || w == "blue" || w == "filter" || w == "transmit") {
    // `color red 1 green 0.5`: components of black.
    putBack(word);
    return colourModifiers(PovValue::colour(0, 0, 0));
  }
  if (peek().isSymbol('(') && isPovFunction(w)) return functionCall(word);
  if (auto it = symbols_.find(std::string(w)); it != symbols_.end()) {
    const PovSymbol& s = it->second;
    if (s.failed) throw PovParseError{};
    if (s.kind != PovSymbolKind::Value) {
      fail(word.span,
           "'" + std::string(w) + "' is " +
               (s.kind == PovSymbolKind::Other ? s.what : std::string(povSymbolKindName(s.kind))) +
               ", not a number, a vector or a colour");
    }
    return s.value;
  }
  if (auto builtin = builtIn(w)) return *builtin;
  if (const PovNamedColour* named = findPovColour(w)) {
    if (coloursIncluded_) {
      return PovValue::colour(named->rgbf[0], named->rgbf[1], named->rgbf[2], named->rgbf[3]);
    }
    out_.error(DiagnosticCode::PovUnknownIdentifier, word.span,
               "'" + std::string(w) + "' is a colour of colors.inc, which is not included")
        .hint = "add #include \"colors.inc\" before it";
    throw PovParseError{};
  }
  unknownIdentifier(word);
}

// --- Names -------------------------------------------------------------------

bool PovEvaluator::fromOtherInclude(std::string_view name) const {
  if (otherIncludes_.empty()) return false;
  if (coloursIncluded_ && findPovColour(name)) return false;
  return std::any_of(name.begin(), name.end(), [](char c) { return c >= 'A' && c <= 'Z'; });
}

void PovEvaluator::unknownIdentifier(const PovToken& word) {
  std::string_view w = word.text;
  if (peek().isSymbol('(')) {
    unsupported(word.span, "the macro call '" + std::string(w) + "(...)'");
    throw PovParseError{};
  }
  if (fromOtherInclude(w)) {
    unsupported(word.span, "'" + std::string(w) + "' (declared in no file this reader reads)",
                "it may come from " + otherIncludes_.front() +
                    ", whose declarations this reader does not read");
    throw PovParseError{};
  }
  Diagnostic& d = out_.error(DiagnosticCode::PovUnknownIdentifier, word.span,
                             "'" + std::string(w.substr(0, 40)) + "' is not declared");
  std::vector<std::string_view> candidates;
  for (const auto& [name, symbol] : symbols_) candidates.push_back(name);
  for (std::string_view name :
       {"x", "y", "z", "pi", "rgb", "color", "image_width", "image_height", "true", "false"}) {
    candidates.push_back(name);
  }
  if (coloursIncluded_) {
    for (std::string_view name : povColourNames()) candidates.push_back(name);
  }
  if (auto guess = suggestKeyword(w, candidates)) {
    d.hint = "did you mean '" + std::string(*guess) + "'?";
    d.fixIt = FixIt{word.span, std::string(*guess)};
  }
  throw PovParseError{};
}

std::optional<PovValue> PovEvaluator::builtIn(std::string_view w) {
  if (w == "x") return PovValue::vector(glm::dvec3(1, 0, 0));
  if (w == "y") return PovValue::vector(glm::dvec3(0, 1, 0));
  if (w == "z") return PovValue::vector(glm::dvec3(0, 0, 1));
  if (w == "t") {
    double c[4] = {0, 0, 0, 1};
    return PovValue::vector(c);
  }
  if (w == "u" || w == "v") {
    double c[2] = {w == "u" ? 1.0 : 0.0, w == "v" ? 1.0 : 0.0};
    return PovValue::vector(c);
  }
  if (w == "pi") return PovValue::number(std::numbers::pi);
  if (w == "tau") return PovValue::number(2.0 * std::numbers::pi);
  if (w == "true" || w == "yes" || w == "on") return PovValue::number(1.0);
  if (w == "false" || w == "no" || w == "off") return PovValue::number(0.0);
  if (w == "image_width") return PovValue::number(options_.pov.imageWidth);
  if (w == "image_height") return PovValue::number(options_.pov.imageHeight);
  if (w == "clock" || w == "clock_on" || w == "initial_clock") return PovValue::number(0.0);
  if (w == "clock_delta" || w == "final_clock") return PovValue::number(1.0);
  if (w == "frame_number" || w == "initial_frame" || w == "final_frame") {
    return PovValue::number(w == "frame_number" ? 0.0 : 1.0);
  }
  if (w == "version") return PovValue::number(3.7);
  return std::nullopt;
}

PovValue PovEvaluator::functionCall(const PovToken& name) {
  expectSymbol('(', "after " + std::string(name.text));
  std::vector<PovValue> args;
  if (!acceptSymbol(')')) {
    for (;;) {
      args.push_back(expression());
      if (acceptSymbol(',')) continue;
      expectSymbol(')', "to close the arguments of " + std::string(name.text));
      break;
    }
  }
  std::string error;
  std::optional<PovValue> value = callPovFunction(name.text, args, error);
  if (!value) fail(name.span, error);
  std::string call = std::string(name.text) + "(";
  bool floats = true;
  for (std::size_t i = 0; i < args.size(); ++i) {
    floats &= args[i].isFloat();
    call += (i ? ", " : "") + (args[i].isFloat() ? formatNumber(args[i].v[0]) : "...");
  }
  requireFinite(*value, name.span, floats ? call + ")" : "'" + std::string(name.text) + "'");
  return *value;
}

// --- Colours -----------------------------------------------------------------

// rgb, rgbf, rgbt, rgbft and their srgb forms, before a float or a vector.
PovValue PovEvaluator::colourKeyword(const PovToken& word) {
  std::string_view w = word.text;
  bool srgb = w.starts_with("srgb");
  std::string_view kind = srgb ? w.substr(1) : w;
  PovValue v = unary();
  PovValue c;
  if (v.isFloat()) {
    double f = v.v[0];
    int count = kind == "rgb" ? 3 : (kind == "rgbft" ? 5 : 4);
    double parts[5] = {f, f, f, f, f};
    v = PovValue::vector(std::span<const double>(parts, count));
  }
  if (v.type == PovValue::Type::Colour) fail(word.span, std::string(w) + " takes a vector");
  int need = kind == "rgb" ? 3 : (kind == "rgbft" ? 5 : 4);
  if (v.size < need) {
    fail(word.span, std::string(w) + " takes a vector of " + std::to_string(need) +
                        " components, found " + std::to_string(v.size));
  }
  c = PovValue::colour(v.v[0], v.v[1], v.v[2]);
  if (kind == "rgbf") c.v[3] = v.v[3];
  if (kind == "rgbt") c.v[4] = v.v[3];
  if (kind == "rgbft") {
    c.v[3] = v.v[3];
    c.v[4] = v.v[4];
  }
  if (srgb) {
    for (int i = 0; i < 3; ++i) c.v[i] = povSrgbToLinear(c.v[i]);
    requireFinite(c, word.span, "the " + std::string(w) + " colour");
  }
  return c;
}

// After `color`: a colour expression, or components of black.
PovValue PovEvaluator::colourAfterKeyword() {
  const PovToken& t = peek();
  if (t.isWord("red") || t.isWord("green") || t.isWord("blue") || t.isWord("filter") ||
      t.isWord("transmit")) {
    return PovValue::colour(0, 0, 0);
  }
  return expression().toColour();
}

PovValue PovEvaluator::colourModifiers(PovValue value) {
  static constexpr std::string_view kParts[] = {"red", "green", "blue", "filter", "transmit"};
  for (;;) {
    const PovToken& t = peek();
    if (t.kind != PovTokenKind::Word) return value;
    auto part = std::find(std::begin(kParts), std::end(kParts), t.text);
    if (part == std::end(kParts)) return value;
    PovToken word = take();
    value = value.toColour();
    PovValue amount = expression();
    if (!amount.isFloat()) fail(word.span, std::string(word.text) + " takes a float");
    value.v[part - std::begin(kParts)] = amount.v[0];
  }
}

PovValue PovEvaluator::colour() {
  if (acceptWord("color") || acceptWord("colour")) return colourModifiers(colourAfterKeyword());
  return colourModifiers(expression()).toColour();
}

// --- Values of one type -----------------------------------------------------

glm::dvec3 PovEvaluator::vectorValue(std::string_view what) {
  SourceSpan where = peek().span;
  PovValue v = expression();
  if (v.type == PovValue::Type::Colour)
    fail(where, std::string(what) + " is a vector, not a colour");
  return v.toVector();
}

double PovEvaluator::floatValue(std::string_view what) {
  SourceSpan where = peek().span;
  PovValue v = expression();
  if (!v.isFloat()) {
    fail(where, std::string(what) + " is a float, not " + std::string(v.typeName()));
  }
  return v.v[0];
}

std::optional<double> PovEvaluator::optionalFloat() {
  const PovToken& t = peek();
  bool starts = t.kind == PovTokenKind::Number || t.isSymbol('(') || t.isSymbol('-') ||
                t.isSymbol('+') ||
                (t.kind == PovTokenKind::Word &&
                 (symbols_.count(std::string(t.text)) || t.isWord("true") || t.isWord("false") ||
                  t.isWord("on") || t.isWord("off") || t.isWord("yes") || t.isWord("no")));
  if (!starts) return std::nullopt;
  return floatValue("the value");
}

}  // namespace scene
