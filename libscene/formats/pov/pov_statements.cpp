#include "libscene/formats/pov/pov_statements.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <numbers>

#include "libscene/formats/pov/pov_keywords.h"
#include "libscene/text/number.h"
#include "libscene/text/reader_support.h"
#include "scenefile/matrix.h"

namespace scene {

namespace {

// POV-Ray's own tolerance for a zero vector (EPSILON in its source).
constexpr double kPovEpsilon = 1e-10;

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

}  // namespace

// --- Statements ----------------------------------------------------------------

bool PovStatementReader::run() {
  try {
    while (peek().kind != PovTokenKind::End) {
      if (out_.full()) throw PovStopReading{};
      statement();
    }
  } catch (const PovStopReading&) {
    return false;
  }
  return true;
}

void PovStatementReader::statement() {
  int depth0 = depth();
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
      forgetStrayBrace();
      fail(brace.span, "'}' closes no block");
    }
    if (t.kind != PovTokenKind::Word) {
      fail(t.span, "expected a statement (camera, light_source, sphere, #declare, ...), found " +
                       describe(t));
    }
    std::string_view word = t.text;
    if (word == "camera") return camera();
    if (word == "light_source") return light();
    if (povObjectKind(word) || word == "object") {
      PovPendingObject object = objectStatement();
      countElement(object.span);
      parts_.objects.push_back(std::move(object));
      return;
    }
    if (word == "global_settings") {
      PovToken keyword = take();
      ignored(keyword.span, "global_settings is ignored",
              "the renderer's ambient term is AMBIENT times each light's colour, and "
              "{0} sets the bounces",
              {{Setting::Depth, ""}});
      skipBlockAfter();
      return;
    }
    if (word == "background") return background();
    if (isPovUnsupportedStatement(word)) {
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
    if (auto guess = suggestKeyword(word, povStatements())) {
      d.hint = "did you mean '" + std::string(*guess) + "'?";
      d.fixIt = FixIt{name.span, std::string(*guess)};
    } else if (isDeclared(word)) {
      d.hint = "a declared object is placed with object { " + std::string(word) + " }";
    }
    throw PovParseError{};
  } catch (const PovParseError&) {
    if (out_.full()) throw PovStopReading{};
    recover(depth0);
  }
}

// The next keyword of a block whose '{' has been read, taken, after
// running directives and gathering transforms into `transform`; nothing
// once the block's '}' is read. `block` names the block in errors.
std::optional<PovToken> PovStatementReader::nextKeyword(std::string_view block,
                                                        PovTransform& transform) {
  while (!acceptSymbol('}')) {
    const PovToken& p = peek();
    if (p.kind == PovTokenKind::Directive) {
      directive();
      continue;
    }
    if (p.kind != PovTokenKind::Word)
      fail(p.span, "expected a " + std::string(block) + " keyword, found " + describe(p));
    if (isPovTransformWord(p.text)) {
      transformItem(transform);
      continue;
    }
    return take();
  }
  return std::nullopt;
}

// --- Camera, lights, background ------------------------------------------------

void PovStatementReader::camera() {
  PovToken keyword = take();
  expectSymbol('{', "after camera");
  PovCameraState c = parts_.camera;
  std::optional<glm::dvec3> lookAt;
  std::optional<double> angle;
  PovTransform transform;
  while (std::optional<PovToken> next = nextKeyword("camera", transform)) {
    cameraItem(*next, c, lookAt, angle);
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
  if (lookAt) lookAtPoint(keyword, *lookAt, c);
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
  parts_.camera = c;
  if (parts_.cameraSpan.known()) {
    ignored(keyword.span, "a later camera statement changes the camera, as in POV-Ray");
  }
  parts_.cameraSpan = keyword.span;
  parts_.cameraComment = keyword.exactComment;
}

// One keyword of a camera statement and its value: a vector into `c`, or
// look_at and angle kept for the fixed order they apply in.
void PovStatementReader::cameraItem(const PovToken& word, PovCameraState& c,
                                    std::optional<glm::dvec3>& lookAt,
                                    std::optional<double>& angle) {
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
  } else if (w == "orthographic" || w == "fisheye" || w == "ultra_wide_angle" || w == "omnimax" ||
             w == "panoramic" || w == "spherical" || w == "cylinder" || w == "mesh_camera" ||
             w == "user_defined") {
    unsupported(word.span, "the " + std::string(w) + " camera",
                "the renderer's camera is a pinhole; {0} reads it as perspective");
    if (w == "cylinder") floatValue("the cylinder camera's type");
    if (w == "mesh_camera" || w == "user_defined") skipBlockAfter();
  } else if (w == "aperture" || w == "blur_samples" || w == "confidence" || w == "variance") {
    expression();
    if (w == "blur_samples" && acceptSymbol(',')) expression();
    loss(word.span,
         "focal blur (" + std::string(w) + ") is dropped: the renderer's camera is a pinhole");
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
    throw PovParseError{};
  }
}

// look_at turns the camera to the point, as POV-Ray does: direction, up
// and right keep their lengths and right its handedness, with up square to
// the new direction in the plane of the sky vector.
void PovStatementReader::lookAtPoint(const PovToken& keyword, const glm::dvec3& lookAt,
                                     PovCameraState& c) {
  double directionLength = glm::length(c.direction);
  double upLength = glm::length(c.up);
  double rightLength = glm::length(c.right);
  double handedness = glm::dot(glm::cross(c.up, c.direction), c.right);
  glm::dvec3 d = lookAt - c.location;
  if (glm::dot(d, d) < kPovEpsilon) {
    fail(keyword.span, "the camera's location and look_at are the same point");
  }
  if (!std::isfinite(glm::dot(d, d))) {
    // Normalising would give 0 or NaN, and every message after it lie.
    out_.error(DiagnosticCode::CameraDegenerate, keyword.span,
               "the camera's look_at is too far from its location: the distance overflows "
               "a double")
        .hint = "scale the scene so that its coordinates stay between 1e-150 and 1e150";
    throw PovParseError{};
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

void PovStatementReader::light() {
  PovToken keyword = take();
  expectSymbol('{', "after light_source");
  PovPendingLight light;
  light.span = keyword.span;
  light.exactComment = keyword.exactComment;
  glm::dvec3 position = vectorValue("the light's location");
  acceptSymbol(',');
  PovValue c = colour();
  light.colour = glm::dvec3(c.v[0], c.v[1], c.v[2]);
  PovTransform transform;
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
               w == "fade_power" || w == "adaptive" || w == "jitter" || w == "area_illumination") {
      std::optional<double> v = w == "jitter" ? optionalFloat() : floatValue(w);
      if ((w == "fade_distance" || w == "fade_power") && v && *v != 0.0) {
        loss(word.span, std::string(w) + " is dropped: the renderer's lights do not fade");
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
      loss(word.span, "a shadowless light casts shadows in the renderer");
    } else if (w == "media_interaction" || w == "media_attenuation") {
      optionalFloat();
    } else if (w == "looks_like" || w == "projected_through" || w == "photons") {
      loss(word.span, std::string(w) + " is dropped");
      skipBlockAfter();
    } else {
      fail(word.span, "'" + std::string(w.substr(0, 40)) + "' is no light_source keyword");
    }
  }
  light.matrix = povTranslation(position);
  if (!transform.identity) light.matrix = transform.m * light.matrix;
  requireFinite(light.matrix, keyword.span, "moving the light");
  countElement(light.span);
  parts_.lights.push_back(light);
}

void PovStatementReader::background() {
  PovToken keyword = take();
  expectSymbol('{', "after background");
  PovValue c = colour();
  expectSymbol('}', "to close background");
  if (c.v[0] != 0.0 || c.v[1] != 0.0 || c.v[2] != 0.0) {
    loss(keyword.span, "the background colour is dropped: a scene file has none",
         "the renderer's background is black");
  }
}

// --- Objects -------------------------------------------------------------------

PovPendingObject PovStatementReader::objectStatement() {
  PovToken keyword = take();
  std::string_view w = keyword.text;
  expectSymbol('{', "after " + std::string(w));
  PovPendingObject object;
  object.span = keyword.span;
  object.exactComment = keyword.exactComment;
  if (std::optional<ObjectKind> kind = povObjectKind(w)) {
    switch (*kind) {
      case ObjectKind::Plane:
        planeShape(keyword, object);
        break;
      case ObjectKind::Sphere:
        sphereShape(keyword, object);
        break;
      case ObjectKind::Cylinder:
        cylinderShape(keyword, object);
        break;
      case ObjectKind::Cube:
        boxShape(keyword, object);
        break;
    }
  } else {
    declaredObject(object);
  }
  requireFinite(object.transform.m, keyword.span, "the " + std::string(w) + "'s shape");
  objectModifiers(object, keyword);
  return object;
}

// Each shape's numbers, as the transformation of the model's unit shape;
// the unit shape as written keeps the identity untouched.
void PovStatementReader::sphereShape(const PovToken& keyword, PovPendingObject& object) {
  object.kind = ObjectKind::Sphere;
  glm::dvec3 centre = vectorValue("the sphere's centre");
  acceptSymbol(',');
  double radius = floatValue("the sphere's radius");
  if (!(radius > 0.0)) {
    degenerate(keyword.span, "a sphere's radius must be above 0, not " + formatNumber(radius));
  }
  if (!(centre == glm::dvec3(0.0) && radius == 1.0)) {
    object.transform.then(povTranslation(centre) * povScaling(glm::dvec3(radius)));
  }
}

void PovStatementReader::boxShape(const PovToken& keyword, PovPendingObject& object) {
  object.kind = ObjectKind::Cube;
  glm::dvec3 a = vectorValue("the box's first corner");
  acceptSymbol(',');
  glm::dvec3 b = vectorValue("the box's second corner");
  glm::dvec3 lo = glm::min(a, b), hi = glm::max(a, b);
  if (lo.x == hi.x || lo.y == hi.y || lo.z == hi.z) {
    degenerate(keyword.span, "the box has a side of length 0");
  }
  if (!(lo == glm::dvec3(-1.0) && hi == glm::dvec3(1.0))) {
    object.transform.then(povTranslation(halfSum(lo, hi)) * povScaling(halfSum(hi, -lo)));
  }
}

void PovStatementReader::cylinderShape(const PovToken& keyword, PovPendingObject& object) {
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
  if (!(length > 0.0)) degenerate(keyword.span, "the cylinder's base and cap are the same point");
  if (!(radius > 0.0)) {
    degenerate(keyword.span, "a cylinder's radius must be above 0, not " + formatNumber(radius));
  }
  if (!(a == glm::dvec3(0, -1, 0) && b == glm::dvec3(0, 1, 0) && radius == 1.0)) {
    glm::dmat4 m = withTranslation(rotationFromY(scaledNormalize(axis)), halfSum(a, b)) *
                   povScaling(glm::dvec3(radius, length * 0.5, radius));
    object.transform.then(m);
  }
}

void PovStatementReader::planeShape(const PovToken& keyword, PovPendingObject& object) {
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
}

// object { Name ... }: a copy of the declared object, to modify.
void PovStatementReader::declaredObject(PovPendingObject& object) {
  if (peek().kind != PovTokenKind::Word) {
    fail(peek().span, "object takes the name of a declared object");
  }
  PovToken name = take();
  const PovSymbol* symbol = findSymbol(name.text);
  if (!symbol) unknownIdentifier(name);
  if (symbol->kind != PovSymbolKind::Object) {
    if (symbol->kind == PovSymbolKind::Other) {
      unsupported(name.span, "'" + std::string(name.text) + "', declared as " + symbol->what);
      throw PovParseError{};
    }
    fail(name.span, "'" + std::string(name.text) + "' is " +
                        std::string(povSymbolKindName(symbol->kind)) + ", not an object");
  }
  const PovPendingObject& declared = *symbol->object;
  object.kind = declared.kind;
  object.transform = declared.transform;
  object.patch = declared.patch;
}

// Objects and lights cost memory in proportion: a bound keeps a file of a
// few bytes per sphere from costing gigabytes.
void PovStatementReader::countElement(SourceSpan span) {
  if (parts_.objects.size() + parts_.lights.size() + 1 > options_.maxObjects) {
    reportTooManyObjects(span, options_.maxObjects, out_);
    throw PovStopReading{};
  }
}

void PovStatementReader::degenerate(SourceSpan span, std::string message) {
  out_.error(DiagnosticCode::PovDegenerate, span, std::move(message));
  throw PovParseError{};
}

void PovStatementReader::objectModifiers(PovPendingObject& object, const PovToken& keyword) {
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
    if (isPovTransformWord(w)) {
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
                          "shadows in the renderer");
    } else if (w == "photons" || w == "radiosity") {
      ignored(word.span, std::string(w) + " is ignored");
      skipBlockAfter();
    } else if (w == "bounded_by" || w == "clipped_by" || w == "interior_texture") {
      unsupported(word.span, "'" + std::string(w) + "'");
      skipBlockAfter();
    } else {
      Diagnostic& d = out_.error(
          DiagnosticCode::PovSyntax, word.span,
          "'" + std::string(w.substr(0, 40)) + "' is no modifier of " + std::string(keyword.text));
      static constexpr std::string_view kModifiers[] = {
          "translate", "rotate",  "scale",    "matrix",   "transform", "pigment",
          "finish",    "texture", "interior", "material", "no_shadow", "hollow"};
      if (auto guess = suggestKeyword(w, kModifiers)) {
        d.hint = "did you mean '" + std::string(*guess) + "'?";
        d.fixIt = FixIt{word.span, std::string(*guess)};
      }
      throw PovParseError{};
    }
  }
}

}  // namespace scene
