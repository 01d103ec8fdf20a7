#include "image/image_formats.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <sstream>

namespace image {

namespace {

// What sfrender knows of a format beyond what OpenImageIO says: its name
// for people, whether it holds linear floating-point values, the bits a
// channel it can store (the default first), and whether sfrender lets its
// writer store alpha where OpenImageIO says it can. A format OpenImageIO
// writes that is not here (one a later OpenImageIO adds) is written as 8-bit
// display values, tagged sRGB, which every writer of integer images takes.
struct KnownFormat {
  std::string_view name;
  std::string_view title;
  bool linear;
  std::array<int, 2> bits;  // a 0 ends the list
  bool alpha = true;
};

// EXR (linear by convention, and the scene-linear format of every renderer)
// and Radiance HDR (linear RGBE) hold floats; EXR defaults to 32-bit float,
// which holds the render's numbers exactly, and takes 16 for half. The
// integer formats whose writers store 16 bits a channel exactly take
// --bits 16. Each limit below is one of OpenImageIO 2.4's writers, found by
// writing and reading back (image_file_test.cpp,
// EveryListedFormatWritesWhatItPromises, holds the table to it):
// - PNM: 16-bit samples come out garbled, so .ppm (sfrender's) is the
//   16-bit PNM;
// - FITS stores 16 bits signed, RLA and IFF lose bits (IFF with alpha);
// - WebP changes the colour of a pixel with alpha, whatever it is told.
constexpr std::array<KnownFormat, 19> kKnownFormats = {{
    {"ppm", "PPM", false, {8, 16}},         {"pnm", "PNM", false, {8, 0}},
    {"png", "PNG", false, {8, 16}},         {"tiff", "TIFF", false, {8, 16}},
    {"openexr", "OpenEXR", true, {32, 16}}, {"hdr", "Radiance HDR", true, {32, 0}},
    {"jpeg", "JPEG", false, {8, 0}},        {"jpeg2000", "JPEG 2000", false, {8, 16}},
    {"webp", "WebP", false, {8, 0}, false}, {"heif", "HEIF", false, {8, 0}},
    {"bmp", "BMP", false, {8, 0}},          {"targa", "Targa", false, {8, 0}},
    {"dpx", "DPX", false, {8, 16}},         {"sgi", "SGI", false, {8, 16}},
    {"fits", "FITS", false, {8, 0}},        {"iff", "IFF", false, {8, 0}},
    {"rla", "RLA", false, {8, 0}},          {"cineon", "Cineon", false, {8, 0}},
    {"psd", "PSD", false, {8, 0}},
}};

const KnownFormat* known(std::string_view name) {
  for (const KnownFormat& f : kKnownFormats) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

// Where a format stands in lists: in the table's order (the common formats
// first), then the others.
std::size_t rank(const ImageFormat& format) {
  const KnownFormat* k = known(format.name);
  return k ? static_cast<std::size_t>(k - kKnownFormats.data()) : kKnownFormats.size();
}

std::string titleOf(const ImageFormat& format) {
  if (const KnownFormat* k = known(format.name)) return std::string(k->title);
  std::string title = format.name;
  std::transform(title.begin(), title.end(), title.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return title;
}

ImageFormat withPolicy(std::string name, std::vector<std::string> extensions, bool alpha) {
  ImageFormat format{std::move(name), std::move(extensions), alpha, false, {8}};
  if (const KnownFormat* k = known(format.name)) {
    format.linear = k->linear;
    format.alpha = format.alpha && k->alpha;
    format.bits.clear();
    for (int b : k->bits) {
      if (b != 0) format.bits.push_back(b);
    }
  }
  return format;
}

// "16 (half)" for a floating-point format's 16 bits, "32 (float)".
std::string bitsName(const ImageFormat& format, int bits) {
  std::string name = std::to_string(bits);
  if (format.linear && bits == 16) name += " (half)";
  if (format.linear && bits == 32) name += " (float)";
  return name;
}

std::string bitsList(const ImageFormat& format) {
  std::string list;
  for (std::size_t i = 0; i < format.bits.size(); ++i) {
    if (i > 0) list += i + 1 == format.bits.size() ? " or " : ", ";
    list += bitsName(format, format.bits[i]);
  }
  return list;
}

std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// The first extension of each format that stores alpha: ".png, .tif, ...".
std::string alphaExtensions(const std::vector<ImageFormat>& formats) {
  std::vector<std::string> first;
  for (const ImageFormat& f : formats) {
    if (f.alpha) first.push_back(f.extensions.front());
  }
  std::string list;
  for (std::size_t i = 0; i < first.size(); ++i) {
    if (i > 0) list += i + 1 == first.size() ? " or " : ", ";
    list += first[i];
  }
  return list;
}

}  // namespace

ImageFormat ppmFormat() {
  return withPolicy("ppm", {".ppm"}, false);
}

ImageFormat pngFormat() {
  return withPolicy("png", {".png"}, true);
}

std::vector<ImageFormat> imageFormatsFrom(std::string_view moduleList) {
  std::vector<ImageFormat> formats = {ppmFormat(), pngFormat()};
  std::istringstream lines{std::string(moduleList)};
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string name, extension;
    int alpha = 0;
    if (!(words >> name >> alpha) || name == "png") continue;
    std::vector<std::string> extensions;
    while (words >> extension) {
      if (extension != "ppm") extensions.push_back("." + lowerCase(extension));
    }
    if (!extensions.empty()) {
      formats.push_back(withPolicy(name, std::move(extensions), alpha != 0));
    }
  }
  std::stable_sort(formats.begin(), formats.end(),
                   [](const ImageFormat& a, const ImageFormat& b) { return rank(a) < rank(b); });
  return formats;
}

const ImageFormat* findImageFormat(const std::vector<ImageFormat>& formats,
                                   const std::filesystem::path& path) {
  std::string extension = lowerCase(path.extension().string());
  for (const ImageFormat& f : formats) {
    if (std::find(f.extensions.begin(), f.extensions.end(), extension) != f.extensions.end()) {
      return &f;
    }
  }
  return nullptr;
}

std::string imageExtensionsOf(const std::vector<ImageFormat>& formats) {
  std::vector<std::string> all;
  for (const ImageFormat& f : formats)
    all.insert(all.end(), f.extensions.begin(), f.extensions.end());
  std::string list;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (i > 0) list += i + 1 == all.size() ? " or " : ", ";
    list += all[i];
  }
  return list;
}

std::string imageFormatTable(const std::vector<ImageFormat>& formats) {
  // Columns: extensions, format, --bits (the default first), alpha, values.
  std::vector<std::string> names;
  std::size_t width = std::string("extensions").size();
  for (const ImageFormat& f : formats) {
    std::string list;
    for (const std::string& e : f.extensions) list += (list.empty() ? "" : " ") + e;
    width = std::max(width, list.size());
    names.push_back(std::move(list));
  }
  auto row = [width](std::string names, std::string title, std::string bits, std::string alpha,
                     std::string values) {
    names.resize(width + 2, ' ');
    title.resize(14, ' ');
    bits.resize(10, ' ');
    alpha.resize(7, ' ');
    return "  " + names + title + bits + alpha + values + "\n";
  };
  std::string table = row("extensions", "format", "--bits", "alpha", "values");
  for (std::size_t i = 0; i < formats.size(); ++i) {
    const ImageFormat& f = formats[i];
    std::string bits;
    for (int b : f.bits) bits += (bits.empty() ? "" : " ") + std::to_string(b);
    table += row(names[i], titleOf(f), bits, f.alpha ? "alpha" : "", f.linear ? "linear" : "sRGB");
  }
  return table;
}

int storedBits(const ImageFormat& format, const ImageOptions& options) {
  return options.bits != 0 ? options.bits : format.bits.front();
}

std::optional<std::string> imageOptionsRefusal(const std::vector<ImageFormat>& formats,
                                               const ImageFormat& format,
                                               const ImageOptions& options) {
  if (options.bits != 0 &&
      std::find(format.bits.begin(), format.bits.end(), options.bits) == format.bits.end()) {
    return titleOf(format) + " images take --bits " + bitsList(format);
  }
  if (options.alpha && !format.alpha) {
    std::string others = alphaExtensions(formats);
    return titleOf(format) + " images have no alpha channel" +
           (others.empty() ? std::string() : "; --alpha takes " + others);
  }
  return std::nullopt;
}

}  // namespace image
