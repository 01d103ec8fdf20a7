#include "libscene/formats/obj/obj_mtl.h"

#include <algorithm>
#include <cmath>

#include "libscene/text/number.h"

namespace scene {

namespace {

// As the glTF reader's kExtrasAgreement: far below any visible change,
// far above the rounding of a number read back from its shortest text.
constexpr double kAgreement = 1e-9;
constexpr double kMaxNs = 1000.0;

bool near(double a, double b) {
  return std::abs(a - b) <= kAgreement * std::max({1.0, std::abs(a), std::abs(b)});
}

template <typename T>
bool sameValue(const std::optional<T>& a, const std::optional<T>& b) {
  if (a.has_value() != b.has_value()) return false;
  if (!a) return true;
  if constexpr (std::is_same_v<T, glm::dvec3>) {
    return near(a->x, b->x) && near(a->y, b->y) && near(a->z, b->z);
  } else {
    return near(static_cast<double>(*a), static_cast<double>(*b));
  }
}

void appendTerm(std::string& out, std::string_view name, const std::optional<glm::dvec3>& v) {
  if (!v) return;
  out += name;
  for (double x : {v->x, v->y, v->z}) {
    out += ' ';
    appendNumber(out, x);
  }
  out += '\n';
}

void appendTerm(std::string& out, std::string_view name, const std::optional<double>& v) {
  if (!v) return;
  out += name;
  out += ' ';
  appendNumber(out, *v);
  out += '\n';
}

double clamp01(double v) {
  return std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0;
}
double mean(const glm::dvec3& v) {
  return (v.x + v.y + v.z) / 3.0;
}

// The numbers after a statement's name: exactly `count`, finite.
bool readTerm(std::string_view rest, std::size_t count, double* values) {
  std::size_t n = 0;
  std::size_t i = 0;
  while (i < rest.size()) {
    while (i < rest.size() && (rest[i] == ' ' || rest[i] == '\t')) ++i;
    std::size_t start = i;
    while (i < rest.size() && rest[i] != ' ' && rest[i] != '\t') ++i;
    if (i == start) break;
    if (n == count) return false;
    ParsedNumber p = parseNumber(rest.substr(start, i - start));
    if (p.status != NumberStatus::Ok || !std::isfinite(p.value)) return false;
    values[n++] = p.value;
  }
  return n == count;
}

}  // namespace

MtlMaterial mtlOf(const Material& m) {
  MtlMaterial v;
  v.ka = m.colour * m.ambient;
  v.kd = m.colour * m.diffuse;
  v.ks = glm::dvec3(m.specular);
  v.ns = std::min(m.shininess, kMaxNs);
  v.ni = m.ri;
  v.d = 1.0 - m.transparency;
  v.illum = m.transparency > 0.0 ? 6 : m.reflectivity > 0.0 ? 3 : 2;
  return v;
}

std::string mtlBlock(const std::string& name, const MtlMaterial& v) {
  std::string out = "newmtl " + name + "\n";
  appendTerm(out, "Ka", v.ka);
  appendTerm(out, "Kd", v.kd);
  appendTerm(out, "Ks", v.ks);
  appendTerm(out, "Ns", v.ns);
  appendTerm(out, "Ni", v.ni);
  appendTerm(out, "d", v.d);
  appendTerm(out, "Tr", v.tr);
  if (v.illum) out += "illum " + std::to_string(*v.illum) + "\n";
  return out + "\n";
}

bool sameMtl(const MtlMaterial& a, const MtlMaterial& b) {
  return sameValue(a.ka, b.ka) && sameValue(a.kd, b.kd) && sameValue(a.ks, b.ks) &&
         sameValue(a.ns, b.ns) && sameValue(a.ni, b.ni) && sameValue(a.d, b.d) &&
         sameValue(a.tr, b.tr) && a.illum == b.illum;
}

Material materialOf(const MtlMaterial& v) {
  Material m;
  if (v.kd) {
    m.colour = glm::max(*v.kd, glm::dvec3(0.0));
    m.diffuse = 1.0;
  }
  if (v.ks) m.specular = clamp01(mean(*v.ks));
  if (v.ns) m.shininess = *v.ns > 0.0 ? *v.ns : 1.0;
  if (v.ni) m.ri = *v.ni > 0.0 ? *v.ni : 1.0;
  if (v.d) {
    m.transparency = clamp01(1.0 - *v.d);
  } else if (v.tr) {
    m.transparency = clamp01(*v.tr);
  }
  return m;
}

std::map<std::string, MtlMaterial> parseMtl(std::string_view text, std::string_view fileName,
                                            DiagnosticList& out) {
  std::map<std::string, MtlMaterial> blocks;
  MtlMaterial* current = nullptr;
  std::uint32_t lineNumber = 0;
  std::size_t warnings = 0;
  while (!text.empty()) {
    ++lineNumber;
    std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) {
      line.remove_suffix(1);
    }
    std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string_view::npos || line[start] == '#') continue;
    line.remove_prefix(start);
    std::size_t space = line.find_first_of(" \t");
    std::string_view name = line.substr(0, space);
    std::string_view rest = space == std::string_view::npos ? "" : line.substr(space + 1);
    if (name == "newmtl") {
      std::size_t first = rest.find_first_not_of(" \t");
      current = &blocks[std::string(first == std::string_view::npos ? "" : rest.substr(first))];
      continue;
    }
    if (!current) continue;
    double v[3];
    bool ok = true;
    if (name == "Ka" || name == "Kd" || name == "Ks") {
      ok = readTerm(rest, 3, v) || (readTerm(rest, 1, v) && (v[1] = v[2] = v[0], true));
      if (ok)
        (name == "Ka"   ? current->ka
         : name == "Kd" ? current->kd
                        : current->ks) = glm::dvec3(v[0], v[1], v[2]);
    } else if (name == "Ns" || name == "Ni" || name == "d" || name == "Tr") {
      ok = readTerm(rest, 1, v);
      if (ok) {
        (name == "Ns"   ? current->ns
         : name == "Ni" ? current->ni
         : name == "d"  ? current->d
                        : current->tr) = v[0];
      }
    } else if (name == "illum") {
      ok = readTerm(rest, 1, v) && v[0] >= 0 && v[0] <= 10 && v[0] == std::floor(v[0]);
      if (ok) current->illum = static_cast<int>(v[0]);
    }
    // A few warnings tell what is wrong; a garbage file gets no more.
    if (!ok && ++warnings <= 10) {
      out.warning(DiagnosticCode::ObjMaterial, {},
                  std::string(fileName) + " line " + std::to_string(lineNumber) + ": '" +
                      std::string(name) + "' needs finite numbers; it is ignored");
    }
  }
  return blocks;
}

}  // namespace scene
