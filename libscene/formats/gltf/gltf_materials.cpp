#include "libscene/formats/gltf/gltf_materials.h"

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "libscene/formats/gltf/gltf_extras.h"
#include "libscene/formats/gltf/gltf_mapping.h"
#include "libscene/text/number.h"

namespace scene::gltf {

namespace {

using Json = nlohmann::json;

PbrMaterial pbrOf(const tinygltf::Material& m) {
  PbrMaterial pbr;
  const std::vector<double>& base = m.pbrMetallicRoughness.baseColorFactor;
  if (base.size() == 4) pbr.baseColor = {base[0], base[1], base[2], base[3]};
  pbr.metallic = m.pbrMetallicRoughness.metallicFactor;
  pbr.roughness = m.pbrMetallicRoughness.roughnessFactor;
  pbr.doubleSided = m.doubleSided;
  Json ext = parseOrNull(m.extensions_json_string);
  auto factor = [&ext](const char* extension, const char* key) -> std::optional<double> {
    if (!ext.is_object() || !ext.contains(extension) || !ext[extension].is_object()) {
      return std::nullopt;
    }
    const Json& e = ext[extension];
    if (!e.contains(key)) {
      // The extensions' own defaults.
      if (std::strcmp(key, "ior") == 0) return 1.5;
      if (std::strcmp(key, "specularFactor") == 0) return 1.0;
      return 0.0;
    }
    return number(e[key]);
  };
  pbr.ior = factor("KHR_materials_ior", "ior");
  pbr.transmission = factor("KHR_materials_transmission", "transmissionFactor");
  pbr.specular = factor("KHR_materials_specular", "specularFactor");
  return pbr;
}

}  // namespace

Material MaterialReader::material(int index, ObjectKind kind) {
  if (index < 0) return Material{};
  const tinygltf::Material& m = c_.model.materials[index];
  PbrMaterial pbr = pbrOf(m);
  if (std::optional<Material> exact = materialExtras(ownExtras(c_.own.materials, index))) {
    if (distanceOfPbr(pbrFromMaterial(*exact, kind), pbr) <= kExtrasAgreement) {
      return *exact;
    }
    c_.out.note(DiagnosticCode::GltfExtrasStale, {},
                "material " + std::to_string(index) + quoted(m.name) +
                    " no longer matches its extras (the file was edited elsewhere): it is read "
                    "from its glTF values");
  }
  if (reported_.insert(index).second) reportLosses(index, pbr);
  Material out = materialFromPbr(pbr);
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(out.colour[i])) out.colour[i] = 1.0;
  }
  return out;
}

void MaterialReader::reportLosses(int index, const PbrMaterial& pbr) {
  const tinygltf::Material& m = c_.model.materials[index];
  if (m.pbrMetallicRoughness.baseColorTexture.index >= 0) {
    c_.out.report(c_.loss, DiagnosticCode::GltfIgnored, {},
                  "material " + std::to_string(index) + quoted(m.name) +
                      ": its base colour texture is ignored; baseColorFactor gives COLOUR");
  }
  if (m.alphaMode != "OPAQUE" && pbr.baseColor[3] < 1.0) {
    c_.out.report(c_.loss, DiagnosticCode::GltfIgnored, {},
                  "material " + std::to_string(index) + quoted(m.name) + ": its alpha of " +
                      formatNumber(pbr.baseColor[3]) + " is ignored");
  }
}

}  // namespace scene::gltf
