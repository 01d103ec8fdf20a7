// sfgen: writes a large, valid, reproducible scene file for the reading
// benchmark, and optionally the same scene in POV-Ray's scene language.
//
// The scene is a CAMERA, two LIGHTs, then N objects of the four kinds, each
// with a random colour and a random matrix T * R * S: S scales each axis by a
// factor in [0.1, 10] (log-uniform), R is a uniformly random rotation, T a
// translation in [-100, 100]^3. The 3x3 block therefore has a condition
// number of at most 100 (plus the rounding of its printed entries), far from
// the validator's 1e12. Numbers are printed with 3 (colours) or 4 (matrix)
// significant digits, as a modelling program might, and records are separated
// by a blank line as sf_writer does: a million objects make about 119 MB.
//
// The pseudo-random numbers come from std::mt19937_64, whose sequence the
// standard fixes, turned into doubles here rather than by the standard
// distributions (whose results differ between standard libraries); rotations
// use only arithmetic and sqrt. A seed thus gives the same bytes everywhere,
// but for the rare scale factor whose last printed digit depends on the last
// bit of std::pow.
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <system_error>

#include <CLI/CLI.hpp>

namespace {

// Significant digits of each kind of number.
constexpr int kColourDigits = 3;
constexpr int kLinearDigits = 4;
constexpr int kTranslationDigits = 4;

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  // Uniform in [0, 1), from the top 53 bits.
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double low, double high) { return low + (high - low) * unit(); }
  std::uint64_t below(std::uint64_t n) { return engine_() % n; }

 private:
  std::mt19937_64 engine_;
};

// Appends `value` with at most `digits` significant digits, as %g would but
// without trailing zeros: "0.125", "-12.5", "1.5e-05". Every form is a valid
// number in both file formats.
void appendNumber(std::string& out, double value, int digits) {
  char buffer[32];
  auto [ptr, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits);
  (void)ec;  // 32 bytes hold any double at this precision
  out.append(buffer, ptr);
}

// A record's values, already printed, so that both outputs carry the same text.
struct Record {
  std::string_view name;  // CAMERA, LIGHT, SPHERE, ...
  std::string colour[3];
  std::string matrix[3][4];  // the first three rows; the fourth is 0 0 0 1
  double value[3][4];        // the values of `matrix`, as read back
};

void setNumber(std::string& text, double value, int digits) {
  text.clear();
  appendNumber(text, value, digits);
}

void setEntry(Record& record, int row, int col, double value, int digits) {
  std::string& text = record.matrix[row][col];
  setNumber(text, value, digits);
  std::from_chars(text.data(), text.data() + text.size(), record.value[row][col]);
}

// A uniformly random rotation: a random unit quaternion, drawn by rejection
// from the 4-ball so that only arithmetic and sqrt are involved.
void randomRotation(Random& random, double r[3][3]) {
  double w, x, y, z, n2;
  do {
    w = random.uniform(-1.0, 1.0);
    x = random.uniform(-1.0, 1.0);
    y = random.uniform(-1.0, 1.0);
    z = random.uniform(-1.0, 1.0);
    n2 = w * w + x * x + y * y + z * z;
  } while (n2 > 1.0 || n2 < 1e-6);
  double n = std::sqrt(n2);
  w /= n;
  x /= n;
  y /= n;
  z /= n;
  r[0][0] = 1 - 2 * (y * y + z * z);
  r[0][1] = 2 * (x * y - w * z);
  r[0][2] = 2 * (x * z + w * y);
  r[1][0] = 2 * (x * y + w * z);
  r[1][1] = 1 - 2 * (x * x + z * z);
  r[1][2] = 2 * (y * z - w * x);
  r[2][0] = 2 * (x * z - w * y);
  r[2][1] = 2 * (y * z + w * x);
  r[2][2] = 1 - 2 * (x * x + y * y);
}

constexpr std::string_view kObjectNames[4] = {"PLANE", "SPHERE", "CYLINDER", "CUBE"};

void randomObject(Random& random, Record& record) {
  record.name = kObjectNames[random.below(4)];
  for (auto& c : record.colour) setNumber(c, random.unit(), kColourDigits);
  double r[3][3];
  randomRotation(random, r);
  double scale[3];
  for (double& s : scale) s = std::pow(10.0, random.uniform(-1.0, 1.0));
  for (int row = 0; row < 3; ++row) {
    // M = R * S: column c of R scaled by s_c.
    for (int col = 0; col < 3; ++col) {
      setEntry(record, row, col, r[row][col] * scale[col], kLinearDigits);
    }
    setEntry(record, row, 3, random.uniform(-100.0, 100.0), kTranslationDigits);
  }
}

// A record whose 3x3 block is the identity: the camera and the lights.
void placedRecord(Record& record, std::string_view name, const double colour[3],
                  const double position[3]) {
  record.name = name;
  for (int i = 0; i < 3; ++i) setNumber(record.colour[i], colour[i], kTranslationDigits);
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) setEntry(record, row, col, row == col ? 1 : 0, 1);
    setEntry(record, row, 3, position[row], kTranslationDigits);
  }
}

void appendSf(std::string& out, const Record& record, bool first) {
  if (!first) out += '\n';  // a blank line between records, as sf_writer does
  out += record.name;
  out += '\n';
  out += record.colour[0];
  out += ' ';
  out += record.colour[1];
  out += ' ';
  out += record.colour[2];
  out += '\n';
  for (const auto& row : record.matrix) {
    out += row[0];
    out += ' ';
    out += row[1];
    out += ' ';
    out += row[2];
    out += ' ';
    out += row[3];
    out += '\n';
  }
  out += "0 0 0 1\n";
}

void appendVector(std::string& out, const std::string& x, const std::string& y,
                  const std::string& z) {
  out += '<';
  out += x;
  out += ',';
  out += y;
  out += ',';
  out += z;
  out += '>';
}

// The camera of both outputs, at (0, 0, 250) looking down -Z.
constexpr double kEye[3] = {0, 0, 250};

// Whether the camera has a negative local y in the record's frame: the sign
// of (c2 x c0) . (eye - t) / det, where c0, c1, c2 are the columns of the 3x3
// block (c2 x c0 over det is the second row of its inverse).
bool cameraBelowPlane(const Record& record) {
  const auto& v = record.value;
  double c0[3] = {v[0][0], v[1][0], v[2][0]};
  double c1[3] = {v[0][1], v[1][1], v[2][1]};
  double c2[3] = {v[0][2], v[1][2], v[2][2]};
  double n[3] = {c2[1] * c0[2] - c2[2] * c0[1], c2[2] * c0[0] - c2[0] * c0[2],
                 c2[0] * c0[1] - c2[1] * c0[0]};
  double det = n[0] * c1[0] + n[1] * c1[1] + n[2] * c1[2];  // c1 . (c2 x c0)
  double side = 0;
  for (int i = 0; i < 3; ++i) side += n[i] * (kEye[i] - v[i][3]);
  return side / det < 0;
}

// POV-Ray's `matrix` multiplies row vectors, so it takes our column-vector
// matrix by columns: the 3x3 block column by column, then the translation.
void appendPov(std::string& out, const Record& record) {
  const auto& m = record.matrix;
  if (record.name == "LIGHT") {
    out += "light_source{";
    appendVector(out, m[0][3], m[1][3], m[2][3]);
    out += " color rgb";
    appendVector(out, record.colour[0], record.colour[1], record.colour[2]);
    out += "}\n";
    return;
  }
  if (record.name == "SPHERE") {
    out += "sphere{0,1";
  } else if (record.name == "CUBE") {
    out += "box{-1,1";
  } else if (record.name == "CYLINDER") {
    out += "cylinder{<0,-1,0>,<0,1,0>,1";
  } else {
    // POV-Ray's plane is a solid half-space, and it refuses to render when
    // the camera lies inside more than a few dozen objects. Of the two
    // half-spaces that share our plane's surface, take the one that leaves
    // the camera out: the same surface, which is all our PLANE is.
    out += cameraBelowPlane(record) ? "plane{-y,0" : "plane{y,0";
  }
  out += " matrix<";
  for (int col = 0; col < 4; ++col) {
    for (int row = 0; row < 3; ++row) {
      if (col || row) out += ',';
      out += m[row][col];
    }
  }
  out += "> pigment{color rgb";
  appendVector(out, record.colour[0], record.colour[1], record.colour[2]);
  out += "}}\n";
}

// Writes through a temporary file renamed at the end, so that an interrupted
// run leaves no partial file that a later run would take for a finished one.
class OutputFile {
 public:
  explicit OutputFile(std::filesystem::path path)
      : path_(std::move(path)), temp_(path_.string() + ".part") {
    file_ = std::fopen(temp_.c_str(), "wb");
    if (!file_) error_ = std::strerror(errno);
  }
  ~OutputFile() {
    if (file_) {
      std::fclose(file_);
      std::filesystem::remove(temp_);
    }
  }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  std::uint64_t bytes() const { return bytes_; }

  // Writes `buffer` out once it is large, or always when `flush`.
  void write(std::string& buffer, bool flush = false) {
    if (!file_ || (!flush && buffer.size() < (1u << 20))) return;
    if (std::fwrite(buffer.data(), 1, buffer.size(), file_) != buffer.size()) {
      error_ = std::strerror(errno);
    }
    bytes_ += buffer.size();
    buffer.clear();
  }

  bool finish(std::string& buffer) {
    write(buffer, true);
    if (!file_) return false;
    bool closed = std::fclose(file_) == 0;
    file_ = nullptr;
    if (!closed && ok()) error_ = std::strerror(errno);
    std::error_code ec;
    if (ok()) std::filesystem::rename(temp_, path_, ec);
    if (ec) error_ = ec.message();
    if (!ok()) std::filesystem::remove(temp_, ec);
    return ok();
  }

 private:
  std::filesystem::path path_;
  std::filesystem::path temp_;
  std::FILE* file_ = nullptr;
  std::string error_;
  std::uint64_t bytes_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes a reproducible random scene file for the reading benchmark."};
  std::filesystem::path output;
  std::filesystem::path povOutput;
  std::uint64_t objects = 1'000'000;
  std::uint64_t seed = 1;
  app.add_option("-o,--output", output, "the .sf file to write")->required();
  app.add_option("-n,--objects", objects, "how many objects after the camera and two lights")
      ->capture_default_str();
  app.add_option("-s,--seed", seed, "seed of the pseudo-random numbers")->capture_default_str();
  app.add_option("--pov", povOutput,
                 "also write the same scene in POV-Ray 3.7 scene language to this file");
  CLI11_PARSE(app, argc, argv);

  OutputFile sf(output);
  if (!sf.ok()) {
    std::cerr << "sfgen: cannot write " << output << ": " << sf.error() << '\n';
    return 1;
  }
  std::optional<OutputFile> pov;
  if (!povOutput.empty()) {
    pov.emplace(povOutput);
    if (!pov->ok()) {
      std::cerr << "sfgen: cannot write " << povOutput << ": " << pov->error() << '\n';
      return 1;
    }
  }
  std::string sfText;
  std::string povText;
  sfText.reserve(2u << 20);
  if (pov) povText.reserve(2u << 20);

  Record record;
  // The camera looks from +Z at the origin, +Y up: the identity rotation.
  const double black[3] = {0, 0, 0};
  placedRecord(record, "CAMERA", black, kEye);
  appendSf(sfText, record, true);
  if (pov) {
    // POV-Ray takes the camera's vectors as given: with right = +X, up = +Y
    // and direction = -Z the image is the one our right-handed camera sees.
    // The format has no field of view; POV-Ray's default (|right| = 1 with
    // |direction| = 1) is used.
    povText +=
        "// Written by sfgen: the same scene as the .sf file beside it.\n"
        "#version 3.7;\n"
        "global_settings{assumed_gamma 1.0}\n"
        "camera{perspective location<0,0,250> direction<0,0,-1> up<0,1,0> right<1,0,0>}\n";
  }
  const double lightColour[2][3] = {{1, 1, 1}, {0.5, 0.5, 0.6}};
  const double lightPosition[2][3] = {{200, 300, 300}, {-250, 150, 100}};
  for (int i = 0; i < 2; ++i) {
    placedRecord(record, "LIGHT", lightColour[i], lightPosition[i]);
    appendSf(sfText, record, false);
    if (pov) appendPov(povText, record);
  }

  Random random(seed);
  for (std::uint64_t i = 0; i < objects; ++i) {
    randomObject(random, record);
    appendSf(sfText, record, false);
    sf.write(sfText);
    if (pov) {
      appendPov(povText, record);
      pov->write(povText);
    }
  }
  if (!sf.finish(sfText)) {
    std::cerr << "sfgen: cannot write " << output << ": " << sf.error() << '\n';
    return 1;
  }
  if (pov && !pov->finish(povText)) {
    std::cerr << "sfgen: cannot write " << povOutput << ": " << pov->error() << '\n';
    return 1;
  }
  std::cout << "sfgen: wrote " << output.string() << " (" << objects << " objects, " << sf.bytes()
            << " bytes)";
  if (pov) std::cout << " and " << povOutput.string() << " (" << pov->bytes() << " bytes)";
  std::cout << '\n';
  return 0;
}
