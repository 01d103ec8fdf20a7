// The part of sfrender that needs OpenImageIO, built as a module that
// image_file.cpp loads with dlopen only when an image is written in a format
// other than PPM: linking OpenImageIO into the program made every run, even
// `sfrender --version`, relocate its ~260 shared libraries (0.26 s of CPU).
// A plain C interface (oiio_module.h), so that nothing of OpenImageIO
// crosses it. Little CMS, which makes the sRGB ICC profile, is one of those
// libraries already.
#include "image/oiio_module.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <lcms2.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace {

void copyText(const std::string& text, char* out, std::size_t size) {
  if (size == 0) return;
  std::size_t n = std::min(text.size(), size - 1);
  std::memcpy(out, text.data(), n);
  out[n] = '\0';
}

// Writers OpenImageIO has that cannot hold a rendered RGB image as it is:
// GIF keeps 256 colours in all, ICO 256 pixels a side, a ZFile one channel
// of depth. (Writers that make no file, "null" and "term", say so
// themselves: supports("procedural").)
constexpr std::array<std::string_view, 3> kUnfitWriters = {"gif", "ico", "zfile"};

bool fitForRenders(const std::string& format) {
  if (std::find(kUnfitWriters.begin(), kUnfitWriters.end(), format) != kUnfitWriters.end()) {
    return false;
  }
  std::unique_ptr<OIIO::ImageOutput> writer = OIIO::ImageOutput::create(format);
  return writer && !writer->supports("procedural");
}

// The line of sfrender_oiio_formats for one format of OpenImageIO's
// extension_list ("tiff:tif,tiff,..."), or nothing when it writes no file
// sfrender can use. An extension counts only if OpenImageIO finds this
// format's writer by it: some of a format's extensions are for reading only
// (.dib, .j2c, .pfm in OpenImageIO 2.4).
std::string formatLine(const std::string& entry, const std::vector<std::string>& writers) {
  std::size_t colon = entry.find(':');
  if (colon == std::string::npos) return {};
  std::string format = entry.substr(0, colon);
  if (std::find(writers.begin(), writers.end(), format) == writers.end()) return {};
  if (!fitForRenders(format)) return {};
  std::string extensions;
  bool alpha = false;
  std::string_view rest = std::string_view(entry).substr(colon + 1);
  while (!rest.empty()) {
    std::size_t comma = rest.find(',');
    std::string extension(rest.substr(0, comma));
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
    std::unique_ptr<OIIO::ImageOutput> writer = OIIO::ImageOutput::create("x." + extension);
    if (!writer || writer->format_name() != format) continue;
    alpha = writer->supports("alpha");
    extensions += " " + extension;
  }
  if (extensions.empty()) return {};
  return format + (alpha ? " 1" : " 0") + extensions + "\n";
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(separator, start);
    if (end == std::string::npos) end = text.size();
    if (end > start) parts.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return parts;
}

// An sRGB ICC profile from Little CMS: version 2.1, which every colour-
// managed reader takes (Firefox, by default, ignores version 4), named as
// the standard's, and dated 2000-01-01 rather than now, so that one render
// makes the same bytes on any day. Empty if it cannot be made.
std::vector<unsigned char> srgbProfile() {
  std::vector<unsigned char> bytes;
  cmsHPROFILE profile = cmsCreate_sRGBProfile();
  if (!profile) return bytes;
  cmsSetProfileVersion(profile, 2.1);
  cmsSetHeaderFlags(profile, cmsEmbeddedProfileTrue);
  if (cmsMLU* name = cmsMLUalloc(nullptr, 1)) {
    cmsMLUsetASCII(name, "en", "US", "sRGB IEC61966-2.1");
    cmsWriteTag(profile, cmsSigProfileDescriptionTag, name);
    cmsMLUfree(name);
  }
  cmsUInt32Number size = 0;
  if (cmsSaveProfileToMem(profile, nullptr, &size) && size >= 128) {
    bytes.resize(size);
    if (!cmsSaveProfileToMem(profile, bytes.data(), &size)) bytes.clear();
  }
  cmsCloseProfile(profile);
  // The header's dateTimeNumber (ICC.1, 7.2.8): six big-endian 16-bit
  // numbers at byte 24. A version 2 profile has no ID (an MD5 of the
  // bytes) to keep in step.
  constexpr std::array<unsigned char, 12> kDate = {0x07, 0xd0, 0, 1, 0, 1, 0, 0, 0, 0, 0, 0};
  if (!bytes.empty()) std::copy(kDate.begin(), kDate.end(), bytes.begin() + 24);
  return bytes;
}

OIIO::TypeDesc storedType(int pixelType) {
  switch (pixelType) {
    case kSfrenderUint16:
      return OIIO::TypeDesc::UINT16;
    case kSfrenderHalf:
      return OIIO::TypeDesc::HALF;
    case kSfrenderFloat:
      return OIIO::TypeDesc::FLOAT;
    default:
      return OIIO::TypeDesc::UINT8;
  }
}

// What the file says of its numbers (docs/RENDERING.md, "Image files"): sRGB
// display values are tagged sRGB, which a PNG writer records as the sRGB
// chunk (with gAMA and cHRM for readers that know no sRGB) and a TIFF, JPEG
// or other writer as Exif's ColorSpace; those that can also get the ICC
// profile (PNG does not: its standard wants sRGB or iCCP, not both). Linear
// values are tagged linear, with their primaries and white (EXR's
// chromaticities).
bool describeColour(const SfrenderImageData& image, const std::string& format,
                    OIIO::ImageSpec& spec, std::string& error) {
  if (image.linear) {
    spec.attribute("oiio:ColorSpace", "Linear");
    // Rec. 709 / sRGB primaries and the D65 white, as x, y pairs.
    static constexpr std::array<float, 8> kRec709 = {0.64f, 0.33f, 0.30f,   0.60f,
                                                     0.15f, 0.06f, 0.3127f, 0.3290f};
    spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), kRec709.data());
    return true;
  }
  spec.attribute("oiio:ColorSpace", "sRGB");
  if (format == "png") return true;
  std::vector<unsigned char> profile = srgbProfile();
  if (profile.empty()) {
    error = "Little CMS could not make the sRGB ICC profile";
    return false;
  }
  spec.attribute("ICCProfile", OIIO::TypeDesc(OIIO::TypeDesc::UINT8, profile.size()),
                 profile.data());
  return true;
}

// The spec of the image to write: its size and channels, where it lies in
// the full image (EXR's data window within its display window, which starts
// at 0, 0; TIFF and PNG record the position as they can), and how alpha is
// stored.
OIIO::ImageSpec specOf(const SfrenderImageData& image) {
  OIIO::ImageSpec spec(image.width, image.height, image.channels, storedType(image.pixelType));
  if (image.channels == 4) spec.alpha_channel = 3;
  spec.x = image.x;
  spec.y = image.y;
  spec.full_x = 0;
  spec.full_y = 0;
  spec.full_width = image.fullWidth;
  spec.full_height = image.fullHeight;
  // Otherwise OpenImageIO divides colour by alpha on the way to a format
  // that stores it straight (PNG), and marks a TIFF's alpha associated.
  if (image.channels == 4 && image.straightAlpha) spec.attribute("oiio:UnassociatedAlpha", 1);
  spec.attribute("pnm:binary", 1);
  return spec;
}

// Writers that choose what they write by the name they open: OpenImageIO
// 2.4's JPEG 2000 takes its codec from the extension (.j2k or .jp2), and
// opened as /proc/self/fd/N it writes nothing and reports success. (HEIF's
// takes AV1 for .avif, which its Compression attribute says instead; DPX
// records the name in its header.)
constexpr std::array<std::string_view, 1> kNamedWriters = {"jpeg2000"};

// Whether `name` ends in `extension` (".avif"), in any case.
bool endsWith(std::string_view name, std::string_view extension) {
  return name.size() >= extension.size() &&
         std::equal(
             extension.begin(), extension.end(), name.end() - extension.size(),
             [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
}

// Writes all of `bytes` to `fd`; false with errno set when it cannot.
bool writeAll(int fd, const std::vector<unsigned char>& bytes) {
  const unsigned char* data = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    ssize_t n = ::write(fd, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      return false;
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) std::size_t sfrender_oiio_formats(char* list,
                                                                         std::size_t size) {
  std::string extensions, writers;
  OIIO::getattribute("extension_list", extensions);
  OIIO::getattribute("output_format_list", writers);
  std::vector<std::string> writerList = split(writers, ',');
  std::string lines;
  for (const std::string& entry : split(extensions, ';')) lines += formatLine(entry, writerList);
  copyText(lines, list, size);
  return lines.size();
}

// `fd` is image_file.cpp's file in memory. Writers open it by its name,
// /proc/self/fd/N, but for those that choose what they write by the name
// they open (kNamedWriters), which get an IOProxy under `name` instead and
// whose bytes are copied into `fd`. Not every writer through an IOProxy: in
// OpenImageIO 2.4 TIFF's then leaves out its Exif directory (the sRGB tag).
__attribute__((visibility("default"))) int sfrender_oiio_write(const char* name,
                                                               const SfrenderImageData* image,
                                                               int fd, char* error,
                                                               std::size_t errorSize) {
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(name);
  if (!out) {
    std::string message = OIIO::geterror();
    copyText(message.empty() ? "no writer takes the name" : message, error, errorSize);
    return 0;
  }
  // OpenImageIO 2.4's JPEG 2000 writer asks OpenJPEG for its default 6
  // resolution levels, which need 32 pixels a side: below that it writes a
  // file no reader opens, and reports nothing.
  if (out->format_name() == std::string_view("jpeg2000") &&
      (image->width < 32 || image->height < 32)) {
    copyText("JPEG 2000 images (OpenImageIO's writer) need 32 pixels a side at least", error,
             errorSize);
    return 0;
  }
  OIIO::ImageSpec spec = specOf(*image);
  // Halves are given as floats, which OpenImageIO rounds to the nearest half.
  OIIO::TypeDesc given = spec.format == OIIO::TypeDesc::HALF ? OIIO::TypeDesc::FLOAT : spec.format;
  std::vector<unsigned char> proxied;
  OIIO::Filesystem::IOVecOutput proxy(proxied);
  bool named = std::find(kNamedWriters.begin(), kNamedWriters.end(), out->format_name()) !=
               kNamedWriters.end();
  if (named) out->set_ioproxy(&proxy);
  std::string message;
  if (out->format_name() == std::string_view("heif")) {
    spec.attribute("Compression", endsWith(name, ".avif") ? "avif" : "heic");
  }
  bool ok = describeColour(*image, out->format_name(), spec, message);
  if (ok) ok = out->open(named ? std::string(name) : "/proc/self/fd/" + std::to_string(fd), spec);
  if (ok) ok = out->write_image(given, image->pixels);
  // geterror() empties the message, so it is taken before close() and after.
  if (!ok && message.empty()) message = out->geterror();
  ok = out->close() && ok;
  if (!ok && message.empty()) message = out->geterror();
  if (ok && named && !writeAll(fd, proxied)) {
    message = std::strerror(errno);
    ok = false;
  }
  if (!ok) {
    copyText(message.empty() ? "the image could not be written" : message, error, errorSize);
    return 0;
  }
  return 1;
}

__attribute__((visibility("default"))) int sfrender_oiio_read(const char* path,
                                                              SfrenderImageRegion* region,
                                                              float* pixels, std::size_t capacity,
                                                              char* error, std::size_t errorSize) {
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::create("openexr");
  if (!in) {
    std::string message = OIIO::geterror();
    copyText(message.empty() ? "OpenImageIO has no OpenEXR reader" : message, error, errorSize);
    return 0;
  }
  if (!in->valid_file(path)) return -1;
  OIIO::ImageSpec spec;
  if (!in->open(path, spec)) {
    std::string message = in->geterror();
    copyText(message.empty() ? "the file could not be opened" : message, error, errorSize);
    return 0;
  }
  *region = SfrenderImageRegion{spec.x,
                                spec.y,
                                spec.width,
                                spec.height,
                                spec.full_x,
                                spec.full_y,
                                spec.full_width,
                                spec.full_height,
                                spec.nchannels,
                                static_cast<int>(spec.format.size() * 8),
                                spec.format.is_floating_point() ? 1 : 0};
  if (!pixels) return 1;
  std::size_t needed =
      std::size_t{3} * static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
  if (spec.nchannels < 3 || spec.depth != 1 || capacity < needed) {
    copyText("the image is not one of three channels of the size read", error, errorSize);
    return 0;
  }
  bool ok = in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, pixels);
  std::string message = ok ? std::string() : in->geterror();
  ok = in->close() && ok;
  if (!ok) {
    copyText(message.empty() ? "the image could not be read" : message, error, errorSize);
    return 0;
  }
  return 1;
}

}  // extern "C"
