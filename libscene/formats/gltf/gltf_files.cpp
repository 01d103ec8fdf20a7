#include "libscene/formats/gltf/gltf_files.h"

#include <cctype>
#include <fstream>
#include <new>

#include "libscene/formats/gltf/glb.h"
#include "scenefile/read.h"

namespace scene::gltf {

namespace {

namespace fs = std::filesystem;

std::optional<std::string> percentDecoded(std::string_view uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] != '%') {
      out += uri[i];
      continue;
    }
    if (i + 2 >= uri.size() || !std::isxdigit(static_cast<unsigned char>(uri[i + 1])) ||
        !std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      return std::nullopt;
    }
    out += static_cast<char>(std::stoi(std::string(uri.substr(i + 1, 2)), nullptr, 16));
    i += 2;
  }
  return out;
}

bool isInside(const fs::path& folder, const fs::path& path) {
  auto f = folder.begin();
  auto p = path.begin();
  for (; f != folder.end(); ++f, ++p) {
    if (p == path.end() || *f != *p) return false;
  }
  return p != path.end();
}

bool noImageDecoding(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                     const unsigned char*, int, void*) {
  return true;
}

// tinygltf's error text, first line only, without its trailing newline.
std::string firstLine(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  if (line.size() > 160) line = line.substr(0, 157) + "...";
  return line.empty() ? "tinygltf could not read it" : line;
}

}  // namespace

// Why a buffer's URI may not be followed, or nothing when it may: only a
// relative path to a regular file inside the glTF's own folder is read.
// `target` is then the file it names.
std::optional<std::string> uriProblem(const std::string& uri, const fs::path& folder,
                                      fs::path& target) {
  if (uri.starts_with("data:")) return std::nullopt;
  std::optional<std::string> decoded = percentDecoded(uri);
  if (!decoded) return "is not a valid URI";
  std::size_t colon = decoded->find(':');
  std::size_t slash = decoded->find('/');
  if (colon != std::string::npos && (slash == std::string::npos || colon < slash)) {
    return "names a scheme ('" + decoded->substr(0, colon) +
           ":'); only files beside the glTF are read";
  }
  if (decoded->find('\0') != std::string::npos) return "holds a NUL byte";
  fs::path relative(*decoded);
  if (relative.is_absolute()) return "is an absolute path; only files beside the glTF are read";
  for (const fs::path& part : relative) {
    if (part == "..") return "climbs out of the glTF's folder with '..'";
  }
  std::error_code ec;
  fs::path base = fs::weakly_canonical(fs::absolute(folder.empty() ? fs::path(".") : folder), ec);
  if (ec || base.empty()) return "cannot be resolved";
  target = fs::weakly_canonical(base / relative, ec);
  if (ec || !isInside(base, target)) return "leads out of the glTF's folder (through a link)";
  if (!fs::exists(target, ec)) return "names a file that does not exist";
  if (!fs::is_regular_file(target, ec)) return "names something that is not a regular file";
  return std::nullopt;
}

bool confinedExists(const std::string& path, void* user) {
  const auto* c = static_cast<const Confinement*>(user);
  std::error_code ec;
  fs::path target = fs::weakly_canonical(path, ec);
  return !ec && isInside(c->folder, target) && fs::is_regular_file(target, ec);
}

std::string unexpandedPath(const std::string& path, void*) {
  return path;
}

bool confinedRead(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                  void* user) {
  if (!confinedExists(path, user)) {
    if (err) *err += "refusing to read '" + path + "'\n";
    return false;
  }
  std::error_code ec;
  std::uintmax_t size = fs::file_size(path, ec);
  // Checked before, and again here in case the file grew since.
  const auto* c = static_cast<const Confinement*>(user);
  if (ec || size > c->maxFileSize) {
    if (err) *err += "cannot read '" + path + "'\n";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  out->resize(static_cast<std::size_t>(size));
  if (size && !in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))) {
    if (err) *err += "cannot read '" + path + "'\n";
    return false;
  }
  return true;
}

bool noWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "the reader writes nothing\n";
  return false;
}

void checkBufferFiles(const nlohmann::json& doc, const fs::path& folder, const ReadOptions& options,
                      DiagnosticList& out) {
  using Json = nlohmann::json;
  if (!doc.contains("buffers") || !doc["buffers"].is_array()) return;
  for (std::size_t i = 0; i < doc["buffers"].size(); ++i) {
    const Json& b = doc["buffers"][i];
    if (!b.is_object() || !b.contains("uri") || !b["uri"].is_string()) continue;
    std::string uri = b["uri"].get<std::string>();
    std::string shown = uri.size() > 80 ? uri.substr(0, 77) + "..." : uri;
    fs::path target;
    if (std::optional<std::string> problem = uriProblem(uri, folder, target)) {
      out.error(DiagnosticCode::GltfExternalFile, {},
                "buffer " + std::to_string(i) + "'s uri '" + shown + "' " + *problem);
      continue;
    }
    std::error_code sizeError;
    std::uintmax_t size = uri.starts_with("data:") ? 0 : fs::file_size(target, sizeError);
    if (!sizeError) {
      checkFileSize(size, options, out, "buffer " + std::to_string(i) + "'s file '" + shown + "'");
    }
  }
}

bool loadModel(const std::string& json, std::optional<std::string_view> bin, bool binary,
               const fs::path& folder, std::uint64_t maxFileSize, tinygltf::Model& model,
               DiagnosticList& out) {
  tinygltf::TinyGLTF loader;
  Confinement confinement;
  std::error_code ec;
  confinement.folder =
      fs::weakly_canonical(fs::absolute(folder.empty() ? fs::path(".") : folder), ec);
  confinement.maxFileSize = maxFileSize;
  loader.SetFsCallbacks({&confinedExists, &unexpandedPath, &confinedRead, &noWrite, &confinement});
  loader.SetImageLoader(&noImageDecoding, nullptr);
  loader.SetStoreOriginalJSONForExtrasAndExtensions(true);
  std::string err;
  std::string warn;
  bool loaded = false;
  try {
    if (binary) {
      std::string glb = encodeGlb(json, bin.value_or(std::string_view{}));
      loaded = loader.LoadBinaryFromMemory(
          &model, &err, &warn, reinterpret_cast<const unsigned char*>(glb.data()),
          static_cast<unsigned int>(glb.size()), confinement.folder.string());
    } else {
      loaded = loader.LoadASCIIFromString(&model, &err, &warn, json.data(),
                                          static_cast<unsigned int>(json.size()),
                                          confinement.folder.string());
    }
  } catch (const std::bad_alloc&) {
    // Out of memory is no property of the file: the tools report it.
    throw;
  } catch (const std::exception& e) {
    err = e.what();
    loaded = false;
  }
  // tinygltf catches what its JSON parser throws, std::bad_alloc too, and
  // returns its text: that is no fault of the file, and goes on as itself.
  if (!loaded && err.starts_with(std::bad_alloc().what())) throw std::bad_alloc();
  if (!loaded) {
    out.error(DiagnosticCode::GltfInvalid, {}, "not a valid glTF 2.0 file: " + firstLine(err));
    return false;
  }
  return true;
}

}  // namespace scene::gltf
