#include "libscene/formats/gltf/gltf_files.h"

#include <cctype>
#include <fstream>

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

}  // namespace scene::gltf
