#include "libscene/formats/pov/pov_reader.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <memory>
#include <numbers>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "scenefile/matrix.h"
#include "libscene/text/number.h"
#include "libscene/formats/pov/pov_lexer.h"
#include "libscene/formats/pov/pov_names.h"
#include "libscene/formats/pov/pov_value.h"
#include "libscene/text/reader_support.h"
#include "scenefile/transform.h"
#include "scenefile/validation.h"

namespace scene {

namespace {

// POV-Ray's own tolerance for a zero vector (EPSILON in its source).
constexpr double kPovEpsilon = 1e-10;
constexpr int kMaxBraceDepth = 256;
constexpr double kDegree = std::numbers::pi / 180.0;

// Thrown after an error is reported: unwinds to the statement, which then
// skips to its end.
struct ParseError {};
// Thrown when reading must stop: a limit, or the error list is full.
struct StopReading {};

// A transformation built up operation by operation. An untouched one is
// exactly the identity, so that a lone `matrix` keeps every bit (even -0).
struct Transform {
  glm::dmat4 m{1.0};
  bool identity = true;

  void then(const glm::dmat4& t) {
    if (identity) {
      m = t;
      identity = false;
    } else {
      m = t * m;
    }
  }
  void then(const Transform& t) {
    if (!t.identity) then(t.m);
  }
};

// What pigment, finish, interior and texture statements set; unset values
// come from what was set before (an object's own over #default over
// POV-Ray's defaults).
struct MaterialPatch {
  std::optional<glm::dvec3> colour;
  std::optional<double> filter, transmit;
  std::optional<double> ambient, diffuse, phong, phongSize, specular, roughness, reflection, ior;

  void merge(const MaterialPatch& later) {
    auto take = [](auto& mine, const auto& theirs) {
      if (theirs) mine = theirs;
    };
    take(colour, later.colour);
    take(filter, later.filter);
    take(transmit, later.transmit);
    take(ambient, later.ambient);
    take(diffuse, later.diffuse);
    take(phong, later.phong);
    take(phongSize, later.phongSize);
    take(specular, later.specular);
    take(roughness, later.roughness);
    take(reflection, later.reflection);
    take(ior, later.ior);
  }
};

// POV-Ray 3.7's default texture and interior.
MaterialPatch povDefaults() {
  MaterialPatch p;
  p.colour = glm::dvec3(0.0);
  p.filter = 0.0;
  p.transmit = 0.0;
  p.ambient = 0.1;
  p.diffuse = 0.6;
  p.phong = 0.0;
  p.phongSize = 40.0;
  p.specular = 0.0;
  p.roughness = 0.05;
  p.reflection = 0.0;
  p.ior = 1.0;
  return p;
}

struct PendingObject {
  ObjectKind kind = ObjectKind::Sphere;
  Transform transform;
  MaterialPatch patch;
  SourceSpan span;
  std::size_t end = 0;
  int exactComment = -1;
};

enum class SymbolKind {
  Value,
  Pigment,
  Finish,
  Texture,
  Interior,
  Material,
  Transform,
  Object,
  Other
};

struct Symbol {
  SymbolKind kind = SymbolKind::Value;
  PovValue value;
  MaterialPatch patch;
  Transform transform;
  std::shared_ptr<const PendingObject> object;
  std::string what;  // for Other: what was declared ("a union", "a string")
  // The value's expression failed (0 / 0, a syntax error): that error was
  // reported, and a use of the name fails without a second one.
  bool failed = false;
};

std::string_view symbolKindName(SymbolKind kind) {
  switch (kind) {
    case SymbolKind::Value:
      return "a value";
    case SymbolKind::Pigment:
      return "a pigment";
    case SymbolKind::Finish:
      return "a finish";
    case SymbolKind::Texture:
      return "a texture";
    case SymbolKind::Interior:
      return "an interior";
    case SymbolKind::Material:
      return "a material";
    case SymbolKind::Transform:
      return "a transform";
    case SymbolKind::Object:
      return "an object";
    case SymbolKind::Other:
      break;
  }
  return "something else";
}

// The camera vectors as POV-Ray keeps them between camera statements.
struct CameraState {
  glm::dvec3 location{0.0};
  glm::dvec3 direction{0.0, 0.0, 1.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  glm::dvec3 right{1.33, 0.0, 0.0};
  glm::dvec3 sky{0.0, 1.0, 0.0};
};

struct PendingLight {
  glm::dmat4 matrix{1.0};
  glm::dvec3 colour{1.0};
  SourceSpan span;
  int exactComment = -1;
};

// The shapes and statements of POV-Ray that are outside the subset, each
// skipped with its block.
// clang-format off
constexpr std::string_view kUnsupportedStatements[] = {
    "union", "difference", "intersection", "merge", "mesh", "mesh2", "torus", "cone", "disc",
    "triangle", "smooth_triangle", "polygon", "prism", "lathe", "sor", "superellipsoid", "blob",
    "height_field", "isosurface", "julia_fractal", "text", "quadric", "cubic", "quartic", "poly",
    "polynomial", "parametric", "bicubic_patch", "sphere_sweep", "ovus", "lemon", "light_group",
    "sky_sphere", "fog", "rainbow", "media", "photons", "radiosity", "spline", "function", "array",
    "dictionary",
};
// clang-format on

// clang-format off
constexpr std::string_view kStatements[] = {
    "camera", "light_source", "sphere", "box", "cylinder", "plane", "object", "global_settings",
    "background",
};
// clang-format on

// Patterns that make a pigment or a normal more than one colour.
// clang-format off
constexpr std::string_view kPatterns[] = {
    "agate", "aoi", "average", "boxed", "brick", "bozo", "bumps", "cells", "checker", "crackle",
    "cubic", "cylindrical", "density_file", "dents", "facets", "function", "gradient", "granite",
    "hexagon", "julia", "leopard", "magnet", "mandel", "marble", "object", "onion", "pavement",
    "pigment_pattern", "planar", "quilted", "radial", "ripples", "slope", "spherical", "spiral1",
    "spiral2", "spotted", "square", "tiling", "triangular", "waves", "wood", "wrinkles",
    "color_map", "colour_map", "pigment_map", "normal_map", "slope_map", "turbulence", "warp",
    "octaves", "omega", "lambda", "frequency", "phase", "tiles", "material_map", "texture_map",
    "uv_mapping", "interpolate",
};
// clang-format on

// Words that name a file's type before its name: POV-Ray would read the file.
// clang-format off
constexpr std::string_view kFileTypes[] = {
    "gif", "tga", "iff", "ppm", "pgm", "png", "jpeg", "tiff", "sys", "exr", "hdr", "ttf", "df3",
};
// clang-format on

template <std::size_t N>
bool contains(const std::string_view (&list)[N], std::string_view word) {
  return std::find(std::begin(list), std::end(list), word) != std::end(list);
}

bool isTransformWord(std::string_view w) {
  return w == "translate" || w == "rotate" || w == "scale" || w == "matrix" || w == "transform";
}

glm::dmat4 translation(const glm::dvec3& v) {
  glm::dmat4 m(1.0);
  m[3] = glm::dvec4(v, 1.0);
  return m;
}

glm::dmat4 scaling(const glm::dvec3& v) {
  glm::dmat4 m(1.0);
  m[0][0] = v.x;
  m[1][1] = v.y;
  m[2][2] = v.z;
  return m;
}

// A rotation that takes +y to the unit vector d: the shortest one, built so
// that it stays accurate for d near -y too.
glm::dmat3 rotationFromY(const glm::dvec3& d) {
  if (d.y < 0.0) {
    glm::dmat3 flip(1.0);
    flip[1][1] = -1.0;
    flip[2][2] = -1.0;  // a half turn about x: y -> -y
    return rotationFromY(-d) * flip;
  }
  // Rodrigues with v = y x d, c = y . d: R = I + [v]x + [v]x^2 / (1 + c).
  glm::dvec3 v(d.z, 0.0, -d.x);
  double k = 1.0 / (1.0 + d.y);
  glm::dmat3 r(1.0);
  // Columns of I + [v]x + k [v]x^2 for v = (vx, 0, vz).
  r[0] = glm::dvec3(1.0 - k * v.z * v.z, v.z, k * v.x * v.z);
  r[1] = glm::dvec3(-v.z, 1.0 - k * (v.x * v.x + v.z * v.z), v.x);
  r[2] = glm::dvec3(k * v.x * v.z, -v.x, 1.0 - k * v.x * v.x);
  return r;
}

// (a + b) / 2, also where a + b overflows (corners at -1e308 and 1e308).
glm::dvec3 halfSum(const glm::dvec3& a, const glm::dvec3& b) {
  glm::dvec3 sum = (a + b) * 0.5;
  if (std::isfinite(sum.x) && std::isfinite(sum.y) && std::isfinite(sum.z)) return sum;
  return a * 0.5 + b * 0.5;
}

glm::dmat4 withTranslation(const glm::dmat3& a, const glm::dvec3& t) {
  glm::dmat4 m(a);
  m[3] = glm::dvec4(t, 1.0);
  return m;
}

// Every matrix of a left-handed scene is conjugated by z -> -z: F M F.
glm::dmat4 mirrorZ(glm::dmat4 m) {
  for (int c = 0; c < 4; ++c) m[c][2] = -m[c][2];
  m[2] = -m[2];
  return m;
}

glm::dvec3 mirrorZ(glm::dvec3 v) {
  return {v.x, v.y, -v.z};
}

bool sameBits(double a, double b) {
  return a == b && std::signbit(a) == std::signbit(b);
}

bool sameBits(const glm::dmat4& a, const glm::dmat4& b) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!sameBits(a[c][r], b[c][r])) return false;
    }
  }
  return true;
}

// The words of an exact comment, and reading numbers from them.
class CommentWords {
 public:
  explicit CommentWords(std::string_view text) {
    std::size_t i = 0;
    while (i < text.size()) {
      while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r')) ++i;
      std::size_t start = i;
      while (i < text.size() && text[i] != ' ' && text[i] != '\t' && text[i] != '\r') ++i;
      if (i > start) words_.push_back(text.substr(start, i - start));
    }
  }
  bool word(std::string_view w) {
    if (next_ < words_.size() && words_[next_] == w) {
      ++next_;
      return true;
    }
    return false;
  }
  std::optional<std::string_view> any() {
    if (next_ >= words_.size()) return std::nullopt;
    return words_[next_++];
  }
  bool number(double& out) {
    if (next_ >= words_.size()) return false;
    ParsedNumber parsed = parseNumber(words_[next_]);
    if (parsed.status != NumberStatus::Ok) return false;
    out = parsed.value;
    ++next_;
    return true;
  }
  bool vector(glm::dvec3& out) { return number(out.x) && number(out.y) && number(out.z); }
  bool matrix(glm::dmat4& out) {
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        if (!number(out[c][r])) return false;
      }
    }
    return true;
  }
  bool done() const { return next_ == words_.size(); }

 private:
  std::vector<std::string_view> words_;
  std::size_t next_ = 0;
};

class PovParser {
 public:
  PovParser(std::string_view text, const ReadOptions& options, PovImport& result)
      : lexer_(text, result.read.diagnostics),
        options_(options),
        result_(result),
        out_(result.read.diagnostics),
        defaults_(povDefaults()) {}

  void run() {
    try {
      while (peek().kind != PovTokenKind::End) {
        if (out_.full()) throw StopReading{};
        statement();
      }
    } catch (const StopReading&) {
      return;
    }
    finish();
  }

 private:
  // --- Tokens ------------------------------------------------------------

  const PovToken& peek(std::size_t k = 0) {
    while (ahead_.size() <= k) {
      ahead_.push_back(lexer_.next());
      if (lexer_.tokenCount() > kMaxPovTokens) {
        out_.error(DiagnosticCode::PovLimit, ahead_.back().span,
                   "the file has more than " + std::to_string(kMaxPovTokens) + " tokens: refused");
        throw StopReading{};
      }
    }
    return ahead_[k];
  }

  PovToken take() {
    PovToken token = peek();
    ahead_.pop_front();
    if (token.isSymbol('{')) {
      if (++depth_ > kMaxBraceDepth) {
        out_.error(DiagnosticCode::PovLimit, token.span,
                   "blocks nest more than " + std::to_string(kMaxBraceDepth) + " deep: refused");
        throw StopReading{};
      }
    } else if (token.isSymbol('}')) {
      --depth_;
    }
    return token;
  }

  bool acceptSymbol(char c) {
    if (!peek().isSymbol(c)) return false;
    take();
    return true;
  }

  bool acceptWord(std::string_view w) {
    if (!peek().isWord(w)) return false;
    take();
    return true;
  }

  std::string describe(const PovToken& t) {
    switch (t.kind) {
      case PovTokenKind::End:
        return "the end of the file";
      case PovTokenKind::String:
        return "a string";
      case PovTokenKind::Directive:
        return "'#" + std::string(t.text) + "'";
      default:
        break;
    }
    return "'" + std::string(t.text.substr(0, 40)) + "'";
  }

  PovToken expectSymbol(char c, std::string_view where) {
    if (!peek().isSymbol(c)) {
      fail(peek().span, std::string("expected '") + c + "' " + std::string(where) + ", found " +
                            describe(peek()));
    }
    return take();
  }

  // --- Reports -----------------------------------------------------------

  [[noreturn]] void fail(SourceSpan span, std::string message, std::string hint = {}) {
    out_.error(DiagnosticCode::PovSyntax, span, std::move(message)).hint = std::move(hint);
    throw ParseError{};
  }

  void unsupported(SourceSpan span, const std::string& what, std::string hint = {}) {
    Severity severity = options_.pov.skipUnsupported ? Severity::Warning : Severity::Error;
    Diagnostic& d =
        out_.report(severity, DiagnosticCode::PovUnsupported, span,
                    what + " is not supported (line " + std::to_string(span.line) + ")");
    d.hint = hint.empty()
                 ? (options_.pov.skipUnsupported ? std::string("skipped")
                                             : std::string("--skip-unsupported converts the rest"))
                 : std::move(hint);
  }

  void loss(SourceSpan span, std::string message, std::string hint = {}) {
    Severity severity = options_.noLoss ? Severity::Error : Severity::Warning;
    out_.report(severity, DiagnosticCode::PovLoss, span, std::move(message)).hint = std::move(hint);
  }

  void ignored(SourceSpan span, std::string message, std::string hint = {}) {
    out_.note(DiagnosticCode::PovIgnored, span, std::move(message)).hint = std::move(hint);
  }

  [[noreturn]] void refuse(SourceSpan span, std::string message, std::string hint = {}) {
    out_.error(DiagnosticCode::PovRefused, span, std::move(message)).hint = std::move(hint);
    throw ParseError{};
  }

  // --- Skipping ----------------------------------------------------------

  // Whether the token, met while skipping, would make POV-Ray read a file.
  void checkFileReading(const PovToken& t) {
    if (t.kind == PovTokenKind::Word && contains(kFileTypes, t.text) &&
        peek().kind == PovTokenKind::String) {
      out_.error(DiagnosticCode::PovRefused, t.span,
                 "'" + std::string(t.text) + " \"" + std::string(peek().text.substr(0, 60)) +
                     "\"' would read another file: refused")
          .hint = "sfconvert reads no file but the scene itself";
    }
  }

  // After an unsupported keyword: its block, if one follows, is skipped.
  void skipBlockAfter() {
    if (!peek().isSymbol('{')) return;
    int depth = depth_;
    take();
    while (depth_ > depth && peek().kind != PovTokenKind::End) {
      PovToken t = take();
      checkFileReading(t);
      if (t.kind == PovTokenKind::Directive) checkDirectiveWhileSkipping(t);
    }
  }

  // Skips to the brace that closes the innermost open block.
  void skipToBlockEnd() {
    int depth = depth_;
    while (peek().kind != PovTokenKind::End && !(depth_ == depth && peek().isSymbol('}'))) {
      PovToken t = take();
      checkFileReading(t);
    }
  }

  // After an error: to the end of the statement it stands in (see the
  // statement loop): out of the blocks opened since, or else to what can
  // start a statement.
  void recover(int depth0) {
    bool inside = depth_ > depth0;
    while (peek().kind != PovTokenKind::End) {
      if (depth_ > depth0) {
        take();
        continue;
      }
      if (inside) return;
      const PovToken& t = peek();
      if (t.kind == PovTokenKind::Directive) return;
      if (t.kind == PovTokenKind::Word &&
          (contains(kStatements, t.text) || contains(kUnsupportedStatements, t.text))) {
        return;
      }
      if (t.isSymbol('}') && depth_ == depth0) return;  // the end of an enclosing block
      if (t.isSymbol('{')) inside = true;
      take();
    }
  }

  // --- Statements --------------------------------------------------------

  void statement() {
    int depth0 = depth_;
    try {
      const PovToken& t = peek();
      if (t.kind == PovTokenKind::Directive) {
        directive();
        return;
      }
      if (t.isSymbol(';')) {
        take();
        return;
      }
      if (t.isSymbol('}')) {
        PovToken brace = take();
        depth_ = std::max(depth_, 0);
        fail(brace.span, "'}' closes no block");
      }
      if (t.kind != PovTokenKind::Word) {
        fail(t.span, "expected a statement (camera, light_source, sphere, #declare, ...), found " +
                         describe(t));
      }
      std::string_view word = t.text;
      if (word == "camera") return camera();
      if (word == "light_source") return light();
      if (word == "sphere" || word == "box" || word == "cylinder" || word == "plane" ||
          word == "object") {
        PendingObject object = objectStatement();
        countElement(object.span);
        objects_.push_back(std::move(object));
        return;
      }
      if (word == "global_settings") {
        PovToken keyword = take();
        ignored(keyword.span, "global_settings is ignored",
                "sfrender's ambient term is AMBIENT times each light's colour, and "
                "--depth sets the bounces");
        skipBlockAfter();
        return;
      }
      if (word == "background") return background();
      if (contains(kUnsupportedStatements, word)) {
        PovToken keyword = take();
        unsupported(keyword.span, "'" + std::string(word) + "'");
        skipBlockAfter();
        return;
      }
      PovToken name = take();
      if (peek().isSymbol('(')) {
        unsupported(name.span, "the macro call '" + std::string(word) + "(...)'");
        skipParentheses();
        return;
      }
      Diagnostic& d = out_.error(DiagnosticCode::PovSyntax, name.span,
                                 "unexpected '" + std::string(word.substr(0, 40)) +
                                     "': expected a statement such as camera, light_source, "
                                     "sphere, box, cylinder, plane or #declare");
      if (auto guess = suggestKeyword(word, kStatements)) {
        d.hint = "did you mean '" + std::string(*guess) + "'?";
        d.fixIt = FixIt{name.span, std::string(*guess)};
      } else if (symbols_.count(std::string(word))) {
        d.hint = "a declared object is placed with object { " + std::string(word) + " }";
      }
      throw ParseError{};
    } catch (const ParseError&) {
      if (out_.full()) throw StopReading{};
      recover(depth0);
    }
  }

  void skipParentheses() {
    int level = 0;
    while (peek().kind != PovTokenKind::End) {
      PovToken t = take();
      if (t.isSymbol('(')) ++level;
      if (t.isSymbol(')') && --level <= 0) return;
    }
  }

  // --- Directives --------------------------------------------------------

  void directive() {
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
    if (name == "default") return defaults();
    if (name == "fopen" || name == "read" || name == "write" || name == "fclose") {
      refuse(d.span, "'#" + std::string(name) + "' reads or writes files: refused",
             "sfconvert reads no file but the scene itself");
    }
    if (name == "if" || name == "ifdef" || name == "ifndef" || name == "switch" ||
        name == "while" || name == "for" || name == "macro") {
      unsupported(d.span, "'#" + std::string(name) + "'",
                  "sfconvert runs no loop, macro or condition; --skip-unsupported skips it to "
                  "its #end");
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

  // Skips a conditional, loop or macro up to its #end, nested ones included.
  void skipDirectiveBlock() {
    int level = 1;
    while (peek().kind != PovTokenKind::End) {
      PovToken t = take();
      checkFileReading(t);
      if (t.kind != PovTokenKind::Directive) continue;
      checkDirectiveWhileSkipping(t);
      std::string_view n = t.text;
      if (n == "if" || n == "ifdef" || n == "ifndef" || n == "switch" || n == "while" ||
          n == "for" || n == "macro") {
        ++level;
      } else if (n == "end" && --level == 0) {
        return;
      }
    }
  }

  // A file is refused for what it would read even where sfconvert skips.
  void checkDirectiveWhileSkipping(const PovToken& t) {
    if (t.text == "include" && peek().kind == PovTokenKind::String &&
        !isPovStandardInclude(peek().text)) {
      out_.error(DiagnosticCode::PovRefused, t.span,
                 "'#include \"" + std::string(peek().text.substr(0, 60)) +
                     "\"' would read another file: refused")
          .hint = "only POV-Ray's standard include files may be included";
    } else if (t.text == "fopen" || t.text == "read") {
      out_.error(DiagnosticCode::PovRefused, t.span,
                 "'#" + std::string(t.text) + "' reads files: refused");
    }
  }

  void include() {
    if (peek().kind != PovTokenKind::String) {
      fail(peek().span, "#include takes a file name in quotes");
    }
    PovToken name = take();
    if (!isPovStandardInclude(name.text)) {
      refuse(name.span,
             "'#include \"" + std::string(name.text.substr(0, 60)) +
                 "\"' would read another file: refused",
             "only POV-Ray's standard include files (colors.inc, textures.inc, ...) may be "
             "included; sfconvert knows colors.inc's colours without reading it");
    }
    if (povIncludeDeclaresColours(name.text)) coloursIncluded_ = true;
    if (name.text != "colors.inc") otherIncludes_.push_back(std::string(name.text));
  }

  void declare(const PovToken& d) {
    if (peek().kind != PovTokenKind::Word) {
      fail(peek().span, "#" + std::string(d.text) + " takes a name, found " + describe(peek()));
    }
    PovToken name = take();
    expectSymbol('=', "after the name of #" + std::string(d.text));
    Symbol symbol;
    const PovToken& t = peek();
    std::string_view w = t.kind == PovTokenKind::Word ? t.text : std::string_view{};
    if (w == "sphere" || w == "box" || w == "cylinder" || w == "plane" || w == "object") {
      symbol.kind = SymbolKind::Object;
      symbol.object = std::make_shared<PendingObject>(objectStatement());
    } else if (w == "pigment" || w == "finish" || w == "texture" || w == "interior" ||
               w == "material") {
      PovToken keyword = take();
      symbol.kind = w == "pigment"    ? SymbolKind::Pigment
                    : w == "finish"   ? SymbolKind::Finish
                    : w == "texture"  ? SymbolKind::Texture
                    : w == "interior" ? SymbolKind::Interior
                                      : SymbolKind::Material;
      materialBlock(keyword, symbol.patch);
    } else if (w == "transform") {
      take();
      symbol.kind = SymbolKind::Transform;
      symbol.transform = transformBlock();
    } else if (t.kind == PovTokenKind::String || w == "camera" || w == "light_source" ||
               w == "normal" || contains(kUnsupportedStatements, w)) {
      PovToken keyword = take();
      std::string what =
          keyword.kind == PovTokenKind::String ? "a string" : "'" + std::string(w) + "'";
      unsupported(keyword.span, "declaring " + what);
      skipBlockAfter();
      symbol.kind = SymbolKind::Other;
      symbol.what = what;
    } else {
      try {
        symbol.value = colourModifiers(expression());
      } catch (const ParseError&) {
        symbol.failed = true;
        symbols_.insert_or_assign(std::string(name.text), std::move(symbol));
        throw;
      }
    }
    acceptSymbol(';');
    bool inserted = symbols_.insert_or_assign(std::string(name.text), std::move(symbol)).second;
    if (inserted && symbols_.size() > kMaxPovDeclarations) {
      out_.error(
          DiagnosticCode::PovLimit, name.span,
          "more than " + std::to_string(kMaxPovDeclarations) + " names are declared: refused");
      throw StopReading{};
    }
  }

  void defaults() {
    expectSymbol('{', "after #default");
    while (!acceptSymbol('}')) {
      const PovToken& t = peek();
      if (t.isWord("pigment") || t.isWord("finish") || t.isWord("texture") ||
          t.isWord("interior")) {
        PovToken keyword = take();
        materialBlock(keyword, defaults_);
      } else if (t.isWord("normal")) {
        PovToken keyword = take();
        unsupported(keyword.span, "a normal pattern");
        skipBlockAfter();
      } else {
        fail(t.span, "#default holds pigment, finish, texture or normal, found " + describe(t));
      }
    }
  }

  // --- Expressions -------------------------------------------------------

  struct NestingGuard {
    explicit NestingGuard(PovParser& p, SourceSpan where) : parser(p) {
      if (++parser.nesting_ > kMaxPovNesting) {
        parser.out_.error(
            DiagnosticCode::PovLimit, where,
            "expressions nest more than " + std::to_string(kMaxPovNesting) + " deep: refused");
        throw StopReading{};
      }
    }
    ~NestingGuard() { --parser.nesting_; }
    PovParser& parser;
  };

  PovValue expression() {
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

  PovValue term() {
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
  PovValue operation(const PovValue& a, const PovValue& b, PovOperator op, SourceSpan where) {
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

  // Reports value-not-finite at `where` and abandons the statement when a
  // component of `value` is NaN or infinite.
  void requireFinite(const PovValue& value, SourceSpan where, const std::string& what) {
    for (int i = 0; i < value.size; ++i) {
      double x = value.v[i];
      if (std::isnan(x)) notFinite(where, what + " gives nan");
      if (std::isinf(x)) notFinite(where, what + " gives " + (x > 0 ? "inf" : "-inf"));
    }
  }

  [[noreturn]] void notFinite(SourceSpan where, const std::string& what) {
    out_.error(DiagnosticCode::ValueNotFinite, where, what + ", which is not a finite number")
        .hint = "every number of a scene must be a finite double";
    throw ParseError{};
  }

  // After a transformation or a shape is built from finite numbers, its
  // matrix can still overflow (a scale by 1e200 twice).
  void requireFinite(const glm::dmat4& m, SourceSpan where, const std::string& what) {
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

  void requireFinite(const glm::dvec3& v, SourceSpan where, const std::string& what) {
    requireFinite(PovValue::vector(v), where, what);
  }

  PovValue unary() {
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
        fail(member.span, std::string(value.typeName()) + " has no component '" +
                              std::string(member.text) + "'");
      }
      value = PovValue::number(*part);
    }
    return value;
  }

  PovValue primary() {
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
      ahead_.push_front(word);
      return colourModifiers(PovValue::colour(0, 0, 0));
    }
    if (peek().isSymbol('(') && isPovFunction(w)) return functionCall(word);
    if (auto it = symbols_.find(std::string(w)); it != symbols_.end()) {
      const Symbol& s = it->second;
      if (s.failed) throw ParseError{};
      if (s.kind != SymbolKind::Value) {
        fail(word.span,
             "'" + std::string(w) + "' is " +
                 (s.kind == SymbolKind::Other ? s.what : std::string(symbolKindName(s.kind))) +
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
      throw ParseError{};
    }
    unknownIdentifier(word);
  }

  // Whether an undeclared name is most likely one of a standard include
  // file that was included but is not read: POV-Ray's keywords are lower
  // case, the include files' names are capitalised.
  bool fromOtherInclude(std::string_view name) const {
    if (otherIncludes_.empty()) return false;
    if (coloursIncluded_ && findPovColour(name)) return false;
    return std::any_of(name.begin(), name.end(), [](char c) { return c >= 'A' && c <= 'Z'; });
  }

  [[noreturn]] void unknownIdentifier(const PovToken& word) {
    std::string_view w = word.text;
    if (peek().isSymbol('(')) {
      unsupported(word.span, "the macro call '" + std::string(w) + "(...)'");
      throw ParseError{};
    }
    if (fromOtherInclude(w)) {
      unsupported(word.span, "'" + std::string(w) + "' (declared in no file sfconvert reads)",
                  "it may come from " + otherIncludes_.front() +
                      ", whose declarations sfconvert does not read");
      throw ParseError{};
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
    throw ParseError{};
  }

  std::optional<PovValue> builtIn(std::string_view w) {
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

  PovValue functionCall(const PovToken& name) {
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

  PovValue colourKeyword(const PovToken& word) {
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
  PovValue colourAfterKeyword() {
    const PovToken& t = peek();
    if (t.isWord("red") || t.isWord("green") || t.isWord("blue") || t.isWord("filter") ||
        t.isWord("transmit")) {
      return PovValue::colour(0, 0, 0);
    }
    return expression().toColour();
  }

  // `red 1 green 0.5 filter 0.2 ...` after a colour.
  PovValue colourModifiers(PovValue value) {
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

  // One number for a colour that the model holds as one (ambient,
  // reflection): the colour's grey, or its mean with a loss reported.
  double greyOf(const PovValue& v, const PovToken& keyword, std::string_view what) {
    if (v.v[0] == v.v[1] && v.v[1] == v.v[2]) return v.v[0];
    double mean = (v.v[0] + v.v[1] + v.v[2]) / 3.0;
    // Three large channels overflow their sum, not their mean.
    if (!std::isfinite(mean)) mean = v.v[0] / 3.0 + v.v[1] / 3.0 + v.v[2] / 3.0;
    loss(keyword.span,
         "a coloured " + std::string(what) + " becomes its mean " + formatNumber(mean),
         std::string(what) + " is one number in the scene model");
    return mean;
  }

  // A colour where one is expected: `color` is optional.
  PovValue colour() {
    if (acceptWord("color") || acceptWord("colour")) return colourModifiers(colourAfterKeyword());
    return colourModifiers(expression()).toColour();
  }

  glm::dvec3 vectorValue(std::string_view what) {
    SourceSpan where = peek().span;
    PovValue v = expression();
    if (v.type == PovValue::Type::Colour)
      fail(where, std::string(what) + " is a vector, not a colour");
    return v.toVector();
  }

  double floatValue(std::string_view what) {
    SourceSpan where = peek().span;
    PovValue v = expression();
    if (!v.isFloat()) {
      fail(where, std::string(what) + " is a float, not " + std::string(v.typeName()));
    }
    return v.v[0];
  }

  // A float when one follows (keywords such as `metallic` take one or none).
  std::optional<double> optionalFloat() {
    const PovToken& t = peek();
    bool starts = t.kind == PovTokenKind::Number || t.isSymbol('(') || t.isSymbol('-') ||
                  t.isSymbol('+') ||
                  (t.kind == PovTokenKind::Word &&
                   (symbols_.count(std::string(t.text)) || t.isWord("true") || t.isWord("false") ||
                    t.isWord("on") || t.isWord("off") || t.isWord("yes") || t.isWord("no")));
    if (!starts) return std::nullopt;
    return floatValue("the value");
  }

  // --- Transformations ---------------------------------------------------

  // One of translate, rotate, scale, matrix, transform, applied to `t`.
  void transformItem(Transform& t) {
    PovToken word = take();
    applyTransformItem(word, t);
    requireFinite(t.m, word.span, "this " + std::string(word.text));
  }

  void applyTransformItem(const PovToken& word, Transform& t) {
    std::string_view w = word.text;
    if (w == "translate") {
      t.then(translation(vectorValue("translate")));
    } else if (w == "rotate") {
      glm::dvec3 angles = vectorValue("rotate");
      // POV-Ray turns about x, then y, then z, by degrees; its matrices are
      // those of FORMATS.md's ROTATE_X/Y/Z (the numbers are the same; only
      // POV-Ray's left-handed picture of them differs).
      const TransformKind kinds[3] = {TransformKind::RotateX, TransformKind::RotateY,
                                      TransformKind::RotateZ};
      for (int i = 0; i < 3; ++i) {
        if (angles[i] == 0.0) continue;
        TransformOp op;
        op.kind = kinds[i];
        op.value = glm::dvec3(angles[i] * kDegree, 0.0, 0.0);
        t.then(transformMatrix(op));
      }
    } else if (w == "scale") {
      glm::dvec3 s = vectorValue("scale");
      for (int i = 0; i < 3; ++i) {
        if (s[i] == 0.0) {
          ignored(word.span,
                  std::string("scale by 0 on ") + "xyz"[i] + " is read as 1, as POV-Ray does");
          s[i] = 1.0;
        }
      }
      t.then(scaling(s));
    } else if (w == "matrix") {
      expectSymbol('<', "after matrix");
      double v[12];
      for (int i = 0; i < 12; ++i) {
        if (i) expectSymbol(',', "between the matrix's 12 numbers");
        v[i] = floatValue("a matrix entry");
      }
      expectSymbol('>', "after the matrix's 12 numbers");
      // POV-Ray's matrix is for row vectors (p' = p * M): its rows are our
      // columns.
      glm::dmat4 m(1.0);
      for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 3; ++r) m[c][r] = v[3 * c + r];
      }
      t.then(m);
    } else {  // transform
      if (peek().kind == PovTokenKind::Word && !peek().isSymbol('{')) {
        t.then(declaredTransform(take()));
      } else {
        t.then(transformBlock());
      }
    }
  }

  Transform declaredTransform(const PovToken& name) {
    auto it = symbols_.find(std::string(name.text));
    if (it == symbols_.end()) unknownIdentifier(name);
    if (it->second.failed) throw ParseError{};
    if (it->second.kind != SymbolKind::Transform) {
      fail(name.span, "'" + std::string(name.text) + "' is " +
                          std::string(symbolKindName(it->second.kind)) + ", not a transform");
    }
    return it->second.transform;
  }

  Transform transformBlock() {
    PovToken open = expectSymbol('{', "after transform");
    Transform t;
    bool inverse = false;
    while (!acceptSymbol('}')) {
      const PovToken& p = peek();
      if (p.kind == PovTokenKind::Word && isTransformWord(p.text)) {
        transformItem(t);
      } else if (p.isWord("inverse")) {
        take();
        inverse = true;
      } else if (p.kind == PovTokenKind::Word && symbols_.count(std::string(p.text))) {
        PovToken name = take();
        t.then(declaredTransform(name));
        requireFinite(t.m, name.span, "the transform '" + std::string(name.text) + "'");
      } else {
        fail(p.span,
             "a transform holds translate, rotate, scale, matrix or inverse, found " + describe(p));
      }
    }
    if (inverse && !t.identity) {
      t.m = glm::inverse(t.m);
      requireFinite(t.m, open.span, "the inverse of this transform");
    }
    return t;
  }

  // --- Materials ---------------------------------------------------------

  // pigment, finish, texture, interior or material { ... } into `patch`.
  void materialBlock(const PovToken& keyword, MaterialPatch& patch) {
    std::string_view w = keyword.text;
    expectSymbol('{', "after " + std::string(w));
    // A declared one of the same kind may come first.
    if (peek().kind == PovTokenKind::Word) {
      auto it = symbols_.find(std::string(peek().text));
      if (it != symbols_.end() && it->second.kind != SymbolKind::Value) {
        PovToken name = take();
        SymbolKind want = w == "pigment"    ? SymbolKind::Pigment
                          : w == "finish"   ? SymbolKind::Finish
                          : w == "texture"  ? SymbolKind::Texture
                          : w == "interior" ? SymbolKind::Interior
                                            : SymbolKind::Material;
        if (it->second.kind != want) {
          fail(name.span, "'" + std::string(name.text) + "' is " +
                              std::string(symbolKindName(it->second.kind)) + ", not " +
                              std::string(symbolKindName(want)));
        }
        patch.merge(it->second.patch);
      } else if (it == symbols_.end() && fromOtherInclude(peek().text)) {
        // T_Stone1 of stones.inc, Glass of glass.inc: names sfconvert does
        // not know. The object keeps the rest of its texture.
        PovToken name = take();
        unsupported(name.span,
                    "the " + std::string(w) + " '" + std::string(name.text) +
                        "' (declared in no file sfconvert reads)",
                    "it may come from " + otherIncludes_.front() +
                        ", whose declarations sfconvert does not read; --skip-unsupported "
                        "keeps the object without it");
        skipToBlockEnd();
      }
    }
    while (!acceptSymbol('}')) {
      const PovToken& t = peek();
      if (t.kind == PovTokenKind::End) fail(keyword.span, std::string(w) + " is not closed");
      if (t.kind == PovTokenKind::Directive) {
        directive();
        continue;
      }
      if (w == "pigment") {
        pigmentItem(patch);
      } else if (w == "finish") {
        finishItem(patch);
      } else if (w == "interior") {
        interiorItem(patch);
      } else if (w == "texture") {
        textureItem(patch);
      } else {
        materialItem(patch);
      }
    }
  }

  void pigmentItem(MaterialPatch& patch) {
    const PovToken& t = peek();
    if (t.kind == PovTokenKind::Word) {
      if (isTransformWord(t.text)) {
        Transform ignoredTransform;  // a plain colour looks the same moved
        transformItem(ignoredTransform);
        return;
      }
      if (t.isWord("quick_color") || t.isWord("quick_colour")) {
        take();
        colour();
        return;
      }
      if (t.isWord("image_map") || t.isWord("bump_map") || t.isWord("material_map")) {
        PovToken word = take();
        refuse(word.span, "'" + std::string(word.text) + "' reads an image file: refused",
               "sfconvert reads no file but the scene itself");
      }
      if (contains(kPatterns, t.text)) {
        PovToken word = take();
        unsupported(word.span, "the pigment pattern '" + std::string(word.text) + "'");
        skipToBlockEnd();
        return;
      }
    }
    PovValue c = colour();
    patch.colour = glm::dvec3(c.v[0], c.v[1], c.v[2]);
    patch.filter = c.v[3];
    patch.transmit = c.v[4];
  }

  void finishItem(MaterialPatch& patch) {
    PovToken t = take();
    std::string_view w = t.text;
    if (t.kind != PovTokenKind::Word)
      fail(t.span, "expected a finish keyword, found " + describe(t));
    if (w == "ambient" || w == "emission") {
      PovValue v = colour();
      if (w == "emission") {
        if (v.v[0] != 0.0 || v.v[1] != 0.0 || v.v[2] != 0.0) {
          loss(t.span, "emission is dropped: sfrender's surfaces do not glow");
        }
        return;
      }
      patch.ambient = greyOf(v, t, "ambient");
    } else if (w == "diffuse") {
      if (acceptWord("albedo")) loss(t.span, "diffuse albedo is read as a plain diffuse");
      patch.diffuse = floatValue("diffuse");
      if (acceptSymbol(',')) {
        double back = floatValue("diffuse's backside");
        if (back != 0.0) loss(t.span, "diffuse backside light is dropped");
      }
    } else if (w == "phong" || w == "specular") {
      if (acceptWord("albedo"))
        loss(t.span, std::string(w) + " albedo is read as a plain " + std::string(w));
      double v = floatValue(w);
      (w == "phong" ? patch.phong : patch.specular) = v;
    } else if (w == "phong_size") {
      patch.phongSize = floatValue(w);
    } else if (w == "roughness") {
      patch.roughness = floatValue(w);
    } else if (w == "reflection") {
      reflection(t, patch);
    } else if (w == "brilliance" || w == "crand" || w == "metallic" || w == "reflection_exponent") {
      std::optional<double> v = w == "metallic" ? optionalFloat() : floatValue(w);
      double neutral = w == "brilliance" ? 1.0 : 0.0;
      if (w == "metallic" && !v) v = 1.0;
      if (*v != neutral) loss(t.span, std::string(w) + " " + formatNumber(*v) + " is dropped");
    } else if (w == "conserve_energy") {
      optionalFloat();
      loss(t.span, "conserve_energy is dropped");
    } else if (w == "irid" || w == "subsurface") {
      loss(t.span, std::string(w) + " is dropped");
      skipBlockAfter();
    } else if (w == "fresnel") {
      optionalFloat();
      loss(t.span,
           "fresnel is dropped: sfrender weighs reflection by Fresnel only for "
           "transparent objects");
    } else {
      Diagnostic& d = out_.error(DiagnosticCode::PovSyntax, t.span,
                                 "'" + std::string(w.substr(0, 40)) + "' is no finish keyword");
      static constexpr std::string_view kFinish[] = {
          "ambient",   "diffuse",    "phong",      "phong_size", "specular",
          "roughness", "reflection", "brilliance", "metallic",   "emission"};
      if (auto guess = suggestKeyword(w, kFinish))
        d.hint = "did you mean '" + std::string(*guess) + "'?";
      throw ParseError{};
    }
  }

  void reflection(const PovToken& t, MaterialPatch& patch) {
    if (!peek().isSymbol('{')) {
      patch.reflection = greyOf(colour(), t, "reflection");
      return;
    }
    take();
    double value = greyOf(colour(), t, "reflection");
    if (acceptSymbol(',')) {
      double h = greyOf(colour(), t, "reflection");
      if (h != value) {
        loss(t.span, "a reflection that varies with the angle (" + formatNumber(value) + " to " +
                         formatNumber(h) + ") becomes " + formatNumber(value));
      }
    }
    while (!acceptSymbol('}')) {
      PovToken w = take();
      if (w.kind != PovTokenKind::Word)
        fail(w.span, "expected a reflection keyword, found " + describe(w));
      if (w.text == "fresnel" || w.text == "metallic") {
        std::optional<double> v = optionalFloat();
        if (v.value_or(1.0) != 0.0) loss(w.span, std::string(w.text) + " reflection is dropped");
      } else if (w.text == "falloff" || w.text == "exponent") {
        double v = floatValue(w.text);
        if (v != 1.0) loss(w.span, std::string(w.text) + " " + formatNumber(v) + " is dropped");
      } else {
        fail(w.span, "'" + std::string(w.text) + "' is no reflection keyword");
      }
    }
    patch.reflection = value;
  }

  void interiorItem(MaterialPatch& patch) {
    PovToken t = take();
    std::string_view w = t.text;
    if (t.kind != PovTokenKind::Word)
      fail(t.span, "expected an interior keyword, found " + describe(t));
    if (w == "ior") {
      patch.ior = floatValue("ior");
    } else if (w == "media") {
      unsupported(t.span, "media");
      skipBlockAfter();
    } else if (w == "caustics" || w == "dispersion" || w == "dispersion_samples" ||
               w == "fade_distance" || w == "fade_power") {
      double v = floatValue(w);
      bool neutral = (w == "dispersion" && v == 1.0) || (w != "dispersion" && v == 0.0);
      if (!neutral) loss(t.span, std::string(w) + " " + formatNumber(v) + " is dropped");
    } else if (w == "fade_color" || w == "fade_colour") {
      colour();
      loss(t.span, std::string(w) + " is dropped");
    } else {
      fail(t.span, "'" + std::string(w.substr(0, 40)) + "' is no interior keyword");
    }
  }

  void textureItem(MaterialPatch& patch) {
    const PovToken& t = peek();
    if (t.isWord("pigment") || t.isWord("finish")) {
      PovToken keyword = take();
      materialBlock(keyword, patch);
    } else if (t.isWord("normal")) {
      PovToken keyword = take();
      unsupported(keyword.span, "a normal pattern");
      skipBlockAfter();
    } else if (t.kind == PovTokenKind::Word && isTransformWord(t.text)) {
      Transform ignoredTransform;
      transformItem(ignoredTransform);
    } else if (t.kind == PovTokenKind::Word && contains(kPatterns, t.text)) {
      PovToken keyword = take();
      unsupported(keyword.span, "the texture pattern '" + std::string(keyword.text) + "'");
      skipToBlockEnd();
    } else {
      fail(t.span, "a texture holds pigment, finish and normal, found " + describe(t));
    }
  }

  void materialItem(MaterialPatch& patch) {
    const PovToken& t = peek();
    if (t.isWord("texture") || t.isWord("interior")) {
      PovToken keyword = take();
      materialBlock(keyword, patch);
    } else if (t.kind == PovTokenKind::Word && isTransformWord(t.text)) {
      Transform ignoredTransform;
      transformItem(ignoredTransform);
    } else {
      fail(t.span, "a material holds texture and interior, found " + describe(t));
    }
  }

  // --- Camera, lights, background ----------------------------------------

  // The next keyword of a block whose '{' has been read, taken, after
  // running directives and gathering transforms into `transform`; nothing
  // once the block's '}' is read. `block` names the block in errors.
  std::optional<PovToken> nextKeyword(std::string_view block, Transform& transform) {
    while (!acceptSymbol('}')) {
      const PovToken& p = peek();
      if (p.kind == PovTokenKind::Directive) {
        directive();
        continue;
      }
      if (p.kind != PovTokenKind::Word)
        fail(p.span, "expected a " + std::string(block) + " keyword, found " + describe(p));
      if (isTransformWord(p.text)) {
        transformItem(transform);
        continue;
      }
      return take();
    }
    return std::nullopt;
  }

  void camera() {
    PovToken keyword = take();
    expectSymbol('{', "after camera");
    CameraState c = camera_;
    std::optional<glm::dvec3> lookAt;
    std::optional<double> angle;
    Transform transform;
    while (std::optional<PovToken> next = nextKeyword("camera", transform)) {
      PovToken word = *next;
      std::string_view w = word.text;
      if (w == "perspective") {
      } else if (w == "location") {
        c.location = vectorValue(w);
      } else if (w == "direction") {
        c.direction = vectorValue(w);
      } else if (w == "up") {
        c.up = vectorValue(w);
      } else if (w == "right") {
        c.right = vectorValue(w);
      } else if (w == "sky") {
        c.sky = vectorValue(w);
      } else if (w == "look_at") {
        lookAt = vectorValue(w);
      } else if (w == "angle") {
        angle = floatValue(w);
        if (*angle < 0.0) fail(word.span, "a negative viewing angle");
        if (*angle >= 180.0) fail(word.span, "the viewing angle must be below 180 degrees");
      } else if (w == "orthographic" || w == "fisheye" || w == "ultra_wide_angle" ||
                 w == "omnimax" || w == "panoramic" || w == "spherical" || w == "cylinder" ||
                 w == "mesh_camera" || w == "user_defined") {
        unsupported(word.span, "the " + std::string(w) + " camera",
                    "sfrender's camera is a pinhole; --skip-unsupported reads it as perspective");
        if (w == "cylinder") floatValue("the cylinder camera's type");
        if (w == "mesh_camera" || w == "user_defined") skipBlockAfter();
      } else if (w == "aperture" || w == "blur_samples" || w == "confidence" || w == "variance") {
        expression();
        if (w == "blur_samples" && acceptSymbol(',')) expression();
        loss(word.span,
             "focal blur (" + std::string(w) + ") is dropped: sfrender's camera is a pinhole");
      } else if (w == "focal_point") {
        vectorValue(w);
      } else if (w == "normal" || w == "bokeh") {
        unsupported(word.span, "a camera " + std::string(w));
        skipBlockAfter();
      } else {
        Diagnostic& d = out_.error(DiagnosticCode::PovSyntax, word.span,
                                   "'" + std::string(w.substr(0, 40)) + "' is no camera keyword");
        static constexpr std::string_view kCamera[] = {
            "location", "look_at", "direction", "up", "right", "sky", "angle", "perspective"};
        if (auto guess = suggestKeyword(w, kCamera)) {
          d.hint = "did you mean '" + std::string(*guess) + "'?";
          d.fixIt = FixIt{word.span, std::string(*guess)};
        }
        throw ParseError{};
      }
    }
    // POV-Ray 3.5 and later apply the modifiers in a fixed order: angle
    // (which sets direction's length from right's), then look_at, then the
    // transformations (POV-Ray's Parse_Camera).
    if (angle && *angle > 0.0) {
      double length = glm::length(c.direction);
      if (length < kPovEpsilon) fail(keyword.span, "the camera's direction has zero length");
      c.direction = c.direction / length *
                    (glm::length(c.right) / std::tan(*angle * std::numbers::pi / 360.0) / 2.0);
    }
    if (lookAt) {
      double directionLength = glm::length(c.direction);
      double upLength = glm::length(c.up);
      double rightLength = glm::length(c.right);
      double handedness = glm::dot(glm::cross(c.up, c.direction), c.right);
      glm::dvec3 d = *lookAt - c.location;
      if (glm::dot(d, d) < kPovEpsilon) {
        fail(keyword.span, "the camera's location and look_at are the same point");
      }
      if (!std::isfinite(glm::dot(d, d))) {
        // Normalising would give 0 or NaN, and every message after it lie.
        out_.error(DiagnosticCode::CameraDegenerate, keyword.span,
                   "the camera's look_at is too far from its location: the distance overflows "
                   "a double")
            .hint = "scale the scene so that its coordinates stay between 1e-150 and 1e150";
        throw ParseError{};
      }
      d = glm::normalize(d);
      glm::dvec3 right = glm::cross(c.sky, d);
      if (std::abs(right.x) < kPovEpsilon && std::abs(right.y) < kPovEpsilon &&
          std::abs(right.z) < kPovEpsilon) {
        // POV-Ray warns and keeps the right vector it had.
        ignored(keyword.span,
                "the camera looks along its sky vector: POV-Ray keeps the right "
                "vector it had");
        right = c.right;
      }
      right = glm::normalize(right);
      c.up = glm::cross(d, right) * upLength;
      c.direction = d * directionLength;
      c.right = right * (handedness > 0.0 ? rightLength : -rightLength);
    }
    if (!transform.identity) {
      glm::dmat3 linear(transform.m);
      c.location = glm::dvec3(transform.m * glm::dvec4(c.location, 1.0));
      c.direction = linear * c.direction;
      c.up = linear * c.up;
      c.right = linear * c.right;
    }
    // A tiny angle, or a transform of large vectors, can overflow them.
    for (const glm::dvec3* v : {&c.location, &c.direction, &c.up, &c.right}) {
      requireFinite(*v, keyword.span, "this camera statement");
    }
    camera_ = c;
    if (cameraSpan_.known()) {
      ignored(keyword.span, "a later camera statement changes the camera, as in POV-Ray");
    }
    cameraSpan_ = keyword.span;
    cameraComment_ = keyword.exactComment;
  }

  void light() {
    PovToken keyword = take();
    expectSymbol('{', "after light_source");
    PendingLight light;
    light.span = keyword.span;
    light.exactComment = keyword.exactComment;
    glm::dvec3 position = vectorValue("the light's location");
    acceptSymbol(',');
    PovValue c = colour();
    light.colour = glm::dvec3(c.v[0], c.v[1], c.v[2]);
    Transform transform;
    while (std::optional<PovToken> next = nextKeyword("light_source", transform)) {
      PovToken word = *next;
      std::string_view w = word.text;
      if (w == "spotlight" || w == "cylinder" || w == "parallel") {
        loss(word.span,
             (w == "spotlight" ? std::string("a spotlight") : "a " + std::string(w) + " light") +
                 " becomes a point light");
      } else if (w == "point_at") {
        vectorValue(w);
      } else if (w == "radius" || w == "falloff" || w == "tightness" || w == "fade_distance" ||
                 w == "fade_power" || w == "adaptive" || w == "jitter" ||
                 w == "area_illumination") {
        std::optional<double> v = w == "jitter" ? optionalFloat() : floatValue(w);
        if ((w == "fade_distance" || w == "fade_power") && v && *v != 0.0) {
          loss(word.span, std::string(w) + " is dropped: sfrender's lights do not fade");
        }
      } else if (w == "area_light") {
        vectorValue("area_light's first axis");
        acceptSymbol(',');
        vectorValue("area_light's second axis");
        acceptSymbol(',');
        floatValue("area_light's first size");
        acceptSymbol(',');
        floatValue("area_light's second size");
        loss(word.span, "an area light becomes a point light");
      } else if (w == "circular" || w == "orient") {
      } else if (w == "shadowless") {
        loss(word.span, "a shadowless light casts shadows in sfrender");
      } else if (w == "media_interaction" || w == "media_attenuation") {
        optionalFloat();
      } else if (w == "looks_like" || w == "projected_through" || w == "photons") {
        loss(word.span, std::string(w) + " is dropped");
        skipBlockAfter();
      } else {
        fail(word.span, "'" + std::string(w.substr(0, 40)) + "' is no light_source keyword");
      }
    }
    light.matrix = translation(position);
    if (!transform.identity) light.matrix = transform.m * light.matrix;
    requireFinite(light.matrix, keyword.span, "moving the light");
    countElement(light.span);
    lights_.push_back(light);
  }

  void background() {
    PovToken keyword = take();
    expectSymbol('{', "after background");
    PovValue c = colour();
    expectSymbol('}', "to close background");
    if (c.v[0] != 0.0 || c.v[1] != 0.0 || c.v[2] != 0.0) {
      loss(keyword.span, "the background colour is dropped: a scene file has none",
           "sfrender's background is black");
    }
  }

  // --- Objects -----------------------------------------------------------

  PendingObject objectStatement() {
    PovToken keyword = take();
    std::string_view w = keyword.text;
    expectSymbol('{', "after " + std::string(w));
    PendingObject object;
    object.span = keyword.span;
    object.exactComment = keyword.exactComment;
    if (w == "sphere") {
      object.kind = ObjectKind::Sphere;
      glm::dvec3 centre = vectorValue("the sphere's centre");
      acceptSymbol(',');
      double radius = floatValue("the sphere's radius");
      if (!(radius > 0.0)) {
        degenerate(keyword.span, "a sphere's radius must be above 0, not " + formatNumber(radius));
      }
      if (!(centre == glm::dvec3(0.0) && radius == 1.0)) {
        object.transform.then(translation(centre) * scaling(glm::dvec3(radius)));
      }
    } else if (w == "box") {
      object.kind = ObjectKind::Cube;
      glm::dvec3 a = vectorValue("the box's first corner");
      acceptSymbol(',');
      glm::dvec3 b = vectorValue("the box's second corner");
      glm::dvec3 lo = glm::min(a, b), hi = glm::max(a, b);
      if (lo.x == hi.x || lo.y == hi.y || lo.z == hi.z) {
        degenerate(keyword.span, "the box has a side of length 0");
      }
      if (!(lo == glm::dvec3(-1.0) && hi == glm::dvec3(1.0))) {
        object.transform.then(translation(halfSum(lo, hi)) * scaling(halfSum(hi, -lo)));
      }
    } else if (w == "cylinder") {
      object.kind = ObjectKind::Cylinder;
      glm::dvec3 a = vectorValue("the cylinder's base");
      acceptSymbol(',');
      glm::dvec3 b = vectorValue("the cylinder's cap");
      acceptSymbol(',');
      double radius = floatValue("the cylinder's radius");
      glm::dvec3 axis = b - a;
      requireFinite(axis, keyword.span, "the cylinder's cap minus its base");
      // Scaled by a power of two: an axis of length 1e-300 is short, not 0
      // (and the same bits as glm::length wherever that does not underflow).
      double length = scaledLength(axis);
      if (!(length > 0.0))
        degenerate(keyword.span, "the cylinder's base and cap are the same point");
      if (!(radius > 0.0)) {
        degenerate(keyword.span,
                   "a cylinder's radius must be above 0, not " + formatNumber(radius));
      }
      if (!(a == glm::dvec3(0, -1, 0) && b == glm::dvec3(0, 1, 0) && radius == 1.0)) {
        glm::dmat4 m = withTranslation(rotationFromY(scaledNormalize(axis)), halfSum(a, b)) *
                       scaling(glm::dvec3(radius, length * 0.5, radius));
        object.transform.then(m);
      }
    } else if (w == "plane") {
      object.kind = ObjectKind::Plane;
      glm::dvec3 normal = vectorValue("the plane's normal");
      acceptSymbol(',');
      double distance = floatValue("the plane's distance");
      double length = scaledLength(normal);
      if (!(length > 0.0)) degenerate(keyword.span, "the plane's normal has length 0");
      if (length < kPovEpsilon) {
        // POV-Ray refuses a normal this short as degenerate too.
        degenerate(keyword.span, "the plane's normal is too short to give a direction (length " +
                                     formatNumber(length) + ", below POV-Ray's 1e-10)");
      }
      // POV-Ray's plane is the surface n . p = distance for the unit normal
      // n (a half-space, whose surface is all a PLANE is). Along +y or -y
      // through the origin it is the PLANE's own y = 0.
      bool ownPlane = normal.x == 0.0 && normal.z == 0.0 && distance == 0.0;
      if (!ownPlane) {
        glm::dvec3 n = scaledNormalize(normal);
        object.transform.then(withTranslation(rotationFromY(n), n * distance));
      }
    } else {  // object { Name ... }
      if (peek().kind != PovTokenKind::Word)
        fail(peek().span, "object takes the name of a declared object");
      PovToken name = take();
      auto it = symbols_.find(std::string(name.text));
      if (it == symbols_.end()) unknownIdentifier(name);
      if (it->second.kind != SymbolKind::Object) {
        if (it->second.kind == SymbolKind::Other) {
          unsupported(name.span,
                      "'" + std::string(name.text) + "', declared as " + it->second.what);
          throw ParseError{};
        }
        fail(name.span, "'" + std::string(name.text) + "' is " +
                            std::string(symbolKindName(it->second.kind)) + ", not an object");
      }
      const PendingObject& declared = *it->second.object;
      object.kind = declared.kind;
      object.transform = declared.transform;
      object.patch = declared.patch;
    }
    requireFinite(object.transform.m, keyword.span, "the " + std::string(w) + "'s shape");
    objectModifiers(object, keyword);
    return object;
  }

  // Objects and lights cost memory in proportion: a bound keeps a file of a
  // few bytes per sphere from costing gigabytes.
  void countElement(SourceSpan span) {
    if (objects_.size() + lights_.size() + 1 > options_.maxObjects) {
      reportTooManyObjects(span, options_.maxObjects, out_);
      throw StopReading{};
    }
  }

  [[noreturn]] void degenerate(SourceSpan span, std::string message) {
    out_.error(DiagnosticCode::PovDegenerate, span, std::move(message));
    throw ParseError{};
  }

  void objectModifiers(PendingObject& object, const PovToken& keyword) {
    for (;;) {
      const PovToken& p = peek();
      if (p.isSymbol('}')) {
        object.end = p.offset;
        take();
        return;
      }
      if (p.kind == PovTokenKind::End)
        fail(keyword.span, std::string(keyword.text) + " is not closed");
      if (p.kind == PovTokenKind::Directive) {
        directive();
        continue;
      }
      if (p.isSymbol(',')) {
        take();
        continue;
      }
      if (p.kind != PovTokenKind::Word) {
        fail(p.span,
             "expected a modifier of " + std::string(keyword.text) + ", found " + describe(p));
      }
      std::string_view w = p.text;
      if (isTransformWord(w)) {
        transformItem(object.transform);
        continue;
      }
      PovToken word = take();
      if (w == "pigment" || w == "finish" || w == "texture" || w == "interior" || w == "material") {
        materialBlock(word, object.patch);
      } else if (w == "normal") {
        unsupported(word.span, "a normal pattern");
        skipBlockAfter();
      } else if (w == "open") {
        if (object.kind == ObjectKind::Cylinder) {
          loss(word.span, "the open cylinder is read closed: a CYLINDER is a solid with caps");
        } else {
          fail(word.span, "'open' belongs to cylinders");
        }
      } else if (w == "hollow" || w == "sturm" || w == "double_illuminate" || w == "inverse" ||
                 w == "no_radiosity") {
        optionalFloat();
        if (w == "inverse" && object.kind != ObjectKind::Plane) {
          ignored(word.span,
                  "inverse is ignored: it turns the solid inside out, which changes "
                  "only its refraction");
        }
      } else if (w == "no_shadow" || w == "no_image" || w == "no_reflection") {
        loss(word.span, std::string(w) +
                            " is dropped: every object shows, reflects and casts "
                            "shadows in sfrender");
      } else if (w == "photons" || w == "radiosity") {
        ignored(word.span, std::string(w) + " is ignored");
        skipBlockAfter();
      } else if (w == "bounded_by" || w == "clipped_by" || w == "interior_texture") {
        unsupported(word.span, "'" + std::string(w) + "'");
        skipBlockAfter();
      } else {
        Diagnostic& d = out_.error(DiagnosticCode::PovSyntax, word.span,
                                   "'" + std::string(w.substr(0, 40)) + "' is no modifier of " +
                                       std::string(keyword.text));
        static constexpr std::string_view kModifiers[] = {
            "translate", "rotate",  "scale",    "matrix",   "transform", "pigment",
            "finish",    "texture", "interior", "material", "no_shadow", "hollow"};
        if (auto guess = suggestKeyword(w, kModifiers)) {
          d.hint = "did you mean '" + std::string(*guess) + "'?";
          d.fixIt = FixIt{word.span, std::string(*guess)};
        }
        throw ParseError{};
      }
    }
  }

  // --- The scene ---------------------------------------------------------

  std::optional<std::string_view> comment(int index) const {
    if (index < 0) return std::nullopt;
    return lexer_.exactComments()[static_cast<std::size_t>(index)].text;
  }

  void finish() {
    Scene& scene = result_.read.scene;
    // A camera whose right vector turns the other way than up x direction
    // (POV-Ray's default) sees a left-handed world: mirror it.
    CameraState c = camera_;
    bool mirrored = glm::dot(glm::cross(c.up, c.direction), c.right) > 0.0;
    result_.view.mirrored = mirrored;
    if (mirrored) {
      c.location = mirrorZ(c.location);
      c.direction = mirrorZ(c.direction);
      c.up = mirrorZ(c.up);
      c.right = mirrorZ(c.right);
    }
    SourceSpan cameraSpan = cameraSpan_.known() ? cameraSpan_ : SourceSpan{1, 1, 0};
    finishCamera(c, cameraSpan);
    for (const PendingLight& pending : lights_) {
      Light light;
      light.matrix = mirrored ? mirrorZ(pending.matrix) : pending.matrix;
      light.colour = pending.colour;
      light.span = pending.span;
      exactLight(light, pending.exactComment);
      RecordSpans spans = RecordSpans::uniform(light.span);
      std::size_t before = out_.errorCount();
      checkColour(light.colour, RecordRole::Light, spans, out_);
      if (out_.errorCount() == before) scene.lights.push_back(light);
    }
    for (PendingObject& pending : objects_) {
      Object object;
      object.kind = pending.kind;
      object.matrix = mirrored ? mirrorZ(pending.transform.m) : pending.transform.m;
      object.span = pending.span;
      std::size_t before = out_.errorCount();
      object.material = material(pending, object);
      checkObjectMatrix(object.matrix, objectKindName(object.kind), object.span, out_);
      exactObject(object, pending.exactComment);
      if (out_.errorCount() == before) {
        scene.objects.push_back(std::move(object));
        result_.objectEnds.push_back(pending.end);
      }
    }
    for (const auto& exact : lexer_.exactComments()) {
      CommentWords words(exact.text);
      if (words.word("output_file")) {
        if (auto name = words.any(); name && words.done()) {
          scene.outputFile = std::string(*name);
          scene.outputFileSpan = exact.span;
        }
      }
    }
    reportView(cameraSpan);
    if (!out_.hasErrors()) checkSceneLevel(scene, out_);
  }

  void finishCamera(const CameraState& c, SourceSpan span) {
    Camera& camera = result_.read.scene.camera;
    camera.span = span;
    double directionLength = glm::length(c.direction);
    if (!(directionLength > 0.0) || !std::isfinite(directionLength)) {
      out_.error(DiagnosticCode::CameraDegenerate, span,
                 std::isfinite(directionLength)
                     ? "the camera's direction has zero length"
                     : "the camera's direction is too long for a double (its length overflows)");
      return;
    }
    glm::dvec3 forward = c.direction / directionLength;
    glm::dvec3 upPart = c.up - glm::dot(c.up, forward) * forward;
    double upLength = glm::length(upPart);
    if (!(upLength > kParallelTolerance * glm::length(c.up))) {
      out_.error(DiagnosticCode::CameraDegenerate, span,
                 "the camera's up vector is zero or parallel to its direction");
      return;
    }
    glm::dvec3 up = upPart / upLength;
    glm::dvec3 right = glm::cross(forward, up);
    double rightLength = glm::dot(c.right, right);
    // sfrender's image plane is square to forward, with right = forward x up.
    double skew = glm::length(c.right - rightLength * right) / glm::length(c.right);
    double tilt = std::abs(glm::dot(c.up, forward)) / glm::length(c.up);
    if (skew > 1e-9 || tilt > 1e-9) {
      loss(span,
           "the camera's direction, up and right are not at right angles: the picture "
           "is sheared in POV-Ray, not in sfrender",
           "sfrender uses direction, and up made square to it");
    }
    camera.matrix = glm::dmat4(1.0);
    camera.matrix[0] = glm::dvec4(right, 0.0);
    camera.matrix[1] = glm::dvec4(up, 0.0);
    camera.matrix[2] = glm::dvec4(-forward, 0.0);
    camera.matrix[3] = glm::dvec4(c.location, 1.0);
    double height = upLength / directionLength;
    result_.view.verticalFovDegrees = 2.0 * std::atan(0.5 * height) / kDegree;
    result_.view.aspectRatio = std::abs(rightLength) / upLength;
    exactCamera(camera, forward, up, cameraComment_);
    checkCameraMatrix(camera.matrix, span, out_);
  }

  // The exact camera of a file sfconvert wrote, when the comment still
  // describes the camera that POV-Ray's statement gives.
  void exactCamera(Camera& camera, const glm::dvec3& forward, const glm::dvec3& up, int index) {
    std::optional<std::string_view> text = comment(index);
    if (!text) return;
    CommentWords words(*text);
    glm::dmat4 m(1.0);
    glm::dvec3 colour(0.0);
    glm::dvec3 lookAt(0.0);
    bool hasLookAt = false;
    bool ok = words.word("camera") && words.word("matrix") && words.matrix(m) &&
              words.word("colour") && words.vector(colour);
    if (ok && words.word("look_at")) hasLookAt = words.vector(lookAt);
    double fov = 0.0, width = 0.0, height = 0.0;
    bool hasView = ok && words.word("fov") && words.number(fov) && words.word("width") &&
                   words.number(width) && words.word("height") && words.number(height);
    ok = ok && words.done();
    if (ok) {
      // Scaled normalisation: axes of length 1e-300 or 1e300 are valid.
      glm::dvec3 f = scaledNormalize(-glm::dvec3(m[2]));
      glm::dvec3 u = scaledNormalize(glm::dvec3(m[1]));
      u = scaledNormalize(u - glm::dot(u, f) * f);
      ok = sameBits(m[3][0], camera.matrix[3][0]) && sameBits(m[3][1], camera.matrix[3][1]) &&
           sameBits(m[3][2], camera.matrix[3][2]) && glm::length(f - forward) < 1e-12 &&
           glm::length(u - up) < 1e-9;
    }
    if (!ok) {
      ignored(camera.span,
              "the sfconvert comment before the camera does not describe it: the "
              "camera is read from the statement");
      return;
    }
    camera.matrix = m;
    camera.colour = colour;
    if (hasLookAt) camera.lookAt = lookAt;
    // The view the writer made the vectors for, when they still show it.
    PovCameraView& view = result_.view;
    if (hasView && width >= 1 && height >= 1 &&
        std::abs(fov - view.verticalFovDegrees) <= 1e-9 * fov &&
        std::abs(width / height - view.aspectRatio) <= 1e-9 * view.aspectRatio) {
      view.verticalFovDegrees = fov;
      view.aspectRatio = width / height;
      viewSize_ = {static_cast<int>(width), static_cast<int>(height)};
    }
  }

  void exactLight(Light& light, int index) {
    std::optional<std::string_view> text = comment(index);
    if (!text) return;
    CommentWords words(*text);
    glm::dmat4 m(1.0);
    bool ok = words.word("light") && words.word("matrix") && words.matrix(m) && words.done() &&
              sameBits(m[3][0], light.matrix[3][0]) && sameBits(m[3][1], light.matrix[3][1]) &&
              sameBits(m[3][2], light.matrix[3][2]) && sameBits(m[3][3], 1.0);
    if (!ok) {
      ignored(light.span,
              "the sfconvert comment before the light does not describe it: the "
              "light is read from the statement");
      return;
    }
    light.matrix = m;
  }

  void exactObject(Object& object, int index) {
    std::optional<std::string_view> text = comment(index);
    if (!text) return;
    CommentWords words(*text);
    std::vector<TransformOp> ops;
    bool ok = words.word("object");
    glm::dmat4 matrix = object.matrix;
    if (ok && words.word("last_row")) {
      // Only the signs of its zeros: the row is 0 0 0 1 in value.
      for (int c = 0; c < 4 && ok; ++c) {
        double v = 0.0;
        ok = words.number(v) && v == matrix[c][3];
        matrix[c][3] = v;
      }
    }
    bool hasTransforms = ok && words.word("transforms");
    while (ok && hasTransforms && !words.done()) {
      std::optional<std::string_view> name = words.any();
      TransformOp op;
      op.span = object.span;
      if (name == "SCALE" || name == "TRANSLATE") {
        op.kind = name == "SCALE" ? TransformKind::Scale : TransformKind::Translate;
        ok = words.vector(op.value);
      } else if (name == "ROTATE_X" || name == "ROTATE_Y" || name == "ROTATE_Z") {
        op.kind = name == "ROTATE_X"   ? TransformKind::RotateX
                  : name == "ROTATE_Y" ? TransformKind::RotateY
                                       : TransformKind::RotateZ;
        ok = words.number(op.value.x);
      } else {
        ok = false;
      }
      ops.push_back(op);
    }
    ok = ok && words.done() && (!hasTransforms || sameBits(composeTransform(ops), matrix));
    if (!ok) {
      ignored(object.span,
              "the sfconvert comment before the object does not describe it: the "
              "object is read from the statement");
      return;
    }
    object.matrix = matrix;
    if (hasTransforms) object.transforms = std::move(ops);
  }

  // The object's material from POV-Ray's texture, each value that the
  // model cannot hold reported.
  Material material(const PendingObject& pending, const Object& object) {
    MaterialPatch p = defaults_;
    p.merge(pending.patch);
    Material m;
    m.colour = *p.colour;
    RecordSpans spans = RecordSpans::uniform(object.span);
    checkColour(m.colour, RecordRole::Object, spans, out_);
    if (*p.filter > 0.0) {
      loss(object.span, "filter " + formatNumber(*p.filter) +
                            " becomes plain transparency: sfrender's light through an object "
                            "is not tinted by its colour");
    }
    // +0 + -0 is +0: without a filter, transmit as written keeps a -0.
    m.transparency = *p.filter == 0.0 ? *p.transmit : *p.filter + *p.transmit;
    m.ambient = *p.ambient;
    m.diffuse = *p.diffuse;
    m.specular = *p.phong;
    m.shininess = *p.phongSize;
    if (*p.specular > 0.0) {
      if (*p.phong == 0.0) {
        // Blinn's (N.H)^(1/roughness) is about Phong's (R.V)^(1/(4 roughness)).
        m.specular = *p.specular;
        m.shininess = 1.0 / (4.0 * *p.roughness);
        if (!std::isfinite(m.shininess)) {
          out_.error(DiagnosticCode::ValueNotFinite, object.span,
                     "roughness " + formatNumber(*p.roughness) +
                         " gives a phong size that is not a finite number")
              .hint = "every number of a scene must be a finite double";
        }
        loss(object.span, "the specular highlight (Blinn) becomes a phong highlight of size " +
                              formatNumber(m.shininess));
      } else {
        loss(object.span, "the specular highlight is dropped: the phong highlight is kept");
      }
    }
    m.reflectivity = *p.reflection;
    m.ri = *p.ior;
    for (MaterialProperty property : kMaterialProperties) {
      double& value = materialValue(m, property);
      if (property == MaterialProperty::Shininess || property == MaterialProperty::Ri) {
        checkMaterialValue(property, value, object.span, out_);
        continue;
      }
      if (value < 0.0 || value > 1.0) {
        double clamped = std::clamp(value, 0.0, 1.0);
        loss(object.span, std::string(materialPropertyName(property)) + " " + formatNumber(value) +
                              " becomes " + formatNumber(clamped) +
                              ": the scene model keeps it in [0, 1]");
        value = clamped;
      }
    }
    return m;
  }

  void reportView(SourceSpan span) {
    const PovCameraView& view = result_.view;
    result_.read.scene.view = View{view.verticalFovDegrees, view.aspectRatio, span};
    int width = viewSize_ ? viewSize_->first : options_.pov.imageWidth;
    int height =
        viewSize_ ? viewSize_->second : static_cast<int>(std::lround(width / view.aspectRatio));
    std::string fov = formatNumber(view.verticalFovDegrees);
    Diagnostic& d =
        out_.note(DiagnosticCode::CameraFov, span,
                  std::string(cameraSpan_.known() ? "the camera"
                                                  : "the file has no camera; POV-Ray's "
                                                    "default camera") +
                      " shows a vertical field of view of " + fov +
                      " degrees at an aspect ratio of " + formatNumber(view.aspectRatio) +
                      (view.mirrored ? ", in a left-handed world (mirrored)" : ""));
    d.hint = "render with sfrender --fov " + fov + " --width " + std::to_string(width) +
             " --height " + std::to_string(std::max(height, 1));
  }

  PovLexer lexer_;
  const ReadOptions& options_;
  PovImport& result_;
  DiagnosticList& out_;
  std::deque<PovToken> ahead_;
  int depth_ = 0;
  int nesting_ = 0;
  std::unordered_map<std::string, Symbol> symbols_;
  bool coloursIncluded_ = false;
  std::vector<std::string> otherIncludes_;
  MaterialPatch defaults_;
  CameraState camera_;
  SourceSpan cameraSpan_;
  int cameraComment_ = -1;
  std::optional<std::pair<int, int>> viewSize_;  // from the exact comment
  std::vector<PendingLight> lights_;
  std::vector<PendingObject> objects_;
};

bool isDirectiveName(std::string_view w) {
  static constexpr std::string_view kDirectives[] = {
      "version", "include", "declare", "local", "default", "macro", "if",
      "ifdef",   "ifndef",  "while",   "for",   "switch",  "undef", "debug",
      "warning", "fopen",   "read",    "write", "end"};
  return contains(kDirectives, w);
}

}  // namespace

PovImport importPov(std::string_view text, std::string fileName, const ReadOptions& options) {
  PovImport result{
      ReadResult{Scene{}, DiagnosticList(std::move(fileName), options.errorLimit)}, {}, {}};
  if (text.size() > kMaxPovBytes) {
    result.read.diagnostics.error(
        DiagnosticCode::PovLimit, SourceSpan{1, 1, 0},
        "the file is larger than " + std::to_string(kMaxPovBytes >> 20) + " MiB: refused");
    return result;
  }
  PovParser(text, options, result).run();
  return result;
}

bool looksLikePov(std::string_view text) {
  std::size_t i = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
  auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  auto isWordChar = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  };
  // Blanks and // comments first, which say nothing (the other formats'
  // readers report them as errors).
  for (;;) {
    while (i < text.size() && isSpace(text[i])) ++i;
    if (text.compare(i, 2, "//") != 0) break;
    while (i < text.size() && text[i] != '\n') ++i;
  }
  if (text.compare(i, 2, "/*") == 0) return true;
  if (i < text.size() && text[i] == '#') {
    std::size_t j = i + 1;
    while (j < text.size() && (text[j] == ' ' || text[j] == '\t')) ++j;
    std::size_t start = j;
    while (j < text.size() && isWordChar(text[j])) ++j;
    return isDirectiveName(text.substr(start, j - start));
  }
  std::size_t start = i;
  while (i < text.size() && isWordChar(text[i])) ++i;
  std::string_view word = text.substr(start, i - start);
  if (!contains(kStatements, word) && !contains(kUnsupportedStatements, word)) return false;
  // The brace may follow on a later line, after comments.
  for (;;) {
    while (i < text.size() && isSpace(text[i])) ++i;
    if (text.compare(i, 2, "//") != 0) break;
    while (i < text.size() && text[i] != '\n') ++i;
  }
  return i < text.size() && text[i] == '{';
}

}  // namespace scene
