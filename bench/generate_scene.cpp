// sfgen: writes a large, valid, reproducible scene file for the benchmarks,
// and optionally the same scene in POV-Ray's scene language.
//
// Two layouts. `--layout floor` (the render benchmark, bench/render_bench.sh)
// is N opaque objects over a floor: see floorScene below. The default,
// `--layout random` (the reading benchmark, bench/run.sh), is a CAMERA, two LIGHTs, then N objects of the four kinds, each
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

// --- The floor layout --------------------------------------------------------
//
// One PLANE (y = 0, light grey), two LIGHTs high above it, and N SPHEREs,
// CUBEs and CYLINDERs (a third each on average) with random colours, each
// T * R * S: S scales each axis by a factor in [0.5, 2] (log-uniform), R is
// a uniformly random rotation, and T puts the object's centre over a random
// point of the square [-L/2, L/2]^2 of the floor, its lowest point 0 to 2
// units above the floor. L = 5 sqrt(N), so that the objects stand equally
// dense whatever N (about a fifth of the floor is covered seen from above).
// The camera stands above one side of the square and looks down across it,
// at the vertical field of view sfrender uses by default (60 degrees).
//
// Everything is opaque and nothing reflects: scene files carry only
// colours, so every object has the default material (ambient 0.1, diffuse
// 0.9, specular 0.9, shininess 200, no reflection, no transparency). The
// POV-Ray file says the same with a #default finish, no fading on the
// lights, and an ambient_light equal to the sum of the lights' colours: our
// ambient term is added once per light, POV-Ray's once per surface.

constexpr double kFloorSpacing = 5.0;
constexpr double kFloorColour[3] = {0.8, 0.8, 0.8};

// Half the height of an object's bounding box along world y: from the
// second row of its 3x3 block, as the printed numbers give it.
double halfHeight(const Record& record) {
  const auto& v = record.value;
  switch (record.name[1]) {
    case 'P': {  // SPHERE
      return std::sqrt(v[1][0] * v[1][0] + v[1][1] * v[1][1] + v[1][2] * v[1][2]);
    }
    case 'Y': {  // CYLINDER: the axis is local y, the disc spans local x and z
      return std::sqrt(v[1][0] * v[1][0] + v[1][2] * v[1][2]) + std::abs(v[1][1]);
    }
    default:  // CUBE
      return std::abs(v[1][0]) + std::abs(v[1][1]) + std::abs(v[1][2]);
  }
}

constexpr std::string_view kSolidNames[3] = {"SPHERE", "CYLINDER", "CUBE"};

void floorObject(Random& random, double side, Record& record) {
  record.name = kSolidNames[random.below(3)];
  for (auto& c : record.colour) setNumber(c, random.uniform(0.15, 1.0), kColourDigits);
  double r[3][3];
  randomRotation(random, r);
  double scale[3];
  for (double& s : scale) s = std::pow(2.0, random.uniform(-1.0, 1.0));
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      setEntry(record, row, col, r[row][col] * scale[col], kLinearDigits);
    }
  }
  double x = random.uniform(-side / 2, side / 2);
  double z = random.uniform(-side / 2, side / 2);
  // The lowest point clears the floor: 1% of margin covers the rounding of
  // the printed height (4 digits, and the height is at least 0.5).
  double y = halfHeight(record) * 1.01 + random.uniform(0.0, 2.0);
  setEntry(record, 0, 3, x, kTranslationDigits + 2);
  setEntry(record, 1, 3, y, kTranslationDigits);
  setEntry(record, 2, 3, z, kTranslationDigits + 2);
}

// The camera of the floor layout: eye, and the orthonormal right, up and
// forward vectors, as the .sf file prints them (shortest round-trip text).
struct FloorCamera {
  double eye[3];
  double right[3];
  double up[3];
  double forward[3];
};

void normalise(double v[3]) {
  double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int i = 0; i < 3; ++i) v[i] /= n;
}

FloorCamera floorCamera(double side) {
  FloorCamera c{};
  // Above the near edge (+Z), a little to the right, looking down at a point
  // a little beyond the centre, so the whole square fills most of the frame.
  const double eye[3] = {0.1 * side, 0.5 * side, 0.62 * side};
  const double target[3] = {0.0, 0.0, 0.04 * side};
  for (int i = 0; i < 3; ++i) {
    c.eye[i] = eye[i];
    c.forward[i] = target[i] - eye[i];
  }
  normalise(c.forward);
  // right = forward x +Y, up = right x forward.
  c.right[0] = -c.forward[2];
  c.right[1] = 0.0;
  c.right[2] = c.forward[0];
  normalise(c.right);
  c.up[0] = c.right[1] * c.forward[2] - c.right[2] * c.forward[1];
  c.up[1] = c.right[2] * c.forward[0] - c.right[0] * c.forward[2];
  c.up[2] = c.right[0] * c.forward[1] - c.right[1] * c.forward[0];
  return c;
}

void appendShortest(std::string& out, double value) {
  char buffer[32];
  auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  (void)ec;
  out.append(buffer, ptr);
}

// The camera record: columns right, up, -forward and the eye.
void appendFloorCameraSf(std::string& out, const FloorCamera& c) {
  out += "CAMERA\n0 0 0\n";
  for (int row = 0; row < 3; ++row) {
    const double entries[4] = {c.right[row], c.up[row], -c.forward[row], c.eye[row]};
    for (int col = 0; col < 4; ++col) {
      if (col) out += ' ';
      appendShortest(out, entries[col] == 0.0 ? 0.0 : entries[col]);
    }
    out += '\n';
  }
  out += "0 0 0 1\n";
}

void appendVector(std::string& out, const double v[3], double factor = 1.0) {
  out += '<';
  for (int i = 0; i < 3; ++i) {
    if (i) out += ',';
    double x = v[i] * factor;
    appendShortest(out, x == 0.0 ? 0.0 : x);
  }
  out += '>';
}

// POV-Ray's camera, from explicit vectors, which it takes as given: the ray
// through the image point (u, v) in [-1/2, 1/2]^2 (u to the right, v up) is
// direction + u * right + v * up. With direction the unit forward vector,
// right and up are our right and up vectors times the image's width and
// height at distance 1: 2 tan(fov/2) * aspect and 2 tan(fov/2). No look_at
// and no angle, so POV-Ray neither recomputes nor mirrors anything.
void appendFloorCameraPov(std::string& out, const FloorCamera& c, double fovDegrees,
                          double aspect) {
  double height = 2.0 * std::tan(fovDegrees * 3.14159265358979323846 / 360.0);
  out += "camera{perspective location";
  appendVector(out, c.eye);
  out += " direction";
  appendVector(out, c.forward);
  out += " right";
  appendVector(out, c.right, height * aspect);
  out += " up";
  appendVector(out, c.up, height);
  out += "}\n";
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
  CLI::App app{"Writes a reproducible random scene file for the reading and render benchmarks."};
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
  std::string layout = "random";
  app.add_option("--layout", layout,
                 "random: objects of the four kinds anywhere (the reading benchmark); "
                 "floor: solids over a floor plane, seen from above (the render benchmark)")
      ->check(CLI::IsMember({"random", "floor"}))
      ->capture_default_str();
  double fov = 60.0;
  double aspect = 16.0 / 9.0;
  app.add_option("--fov", fov,
                 "floor layout: the vertical field of view of the POV-Ray camera, in degrees "
                 "(sfrender's --fov)")
      ->check(CLI::Range(0.001, 179.999))
      ->capture_default_str();
  app.add_option("--aspect", aspect,
                 "floor layout: width / height of the image the POV-Ray camera is for")
      ->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);
  const bool floor = layout == "floor";

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
  const double side = kFloorSpacing * std::sqrt(static_cast<double>(objects));
  if (floor) {
    FloorCamera camera = floorCamera(side);
    appendFloorCameraSf(sfText, camera);
    if (pov) {
      povText +=
          "// Written by sfgen --layout floor: the same scene as the .sf file beside it,\n"
          "// for an image of the given aspect ratio; render with File_Gamma=1.0 for\n"
          "// the linear values sfrender writes.\n"
          "#version 3.7;\n"
          "global_settings{assumed_gamma 1.0 max_trace_level 5 ambient_light rgb<1.5,1.5,1.6>}\n"
          "background{rgb 0}\n"
          "#default{finish{ambient 0.1 diffuse 0.9 phong 0.9 phong_size 200}}\n";
      appendFloorCameraPov(povText, camera, fov, aspect);
    }
  }
  // The camera looks from +Z at the origin, +Y up: the identity rotation.
  const double black[3] = {0, 0, 0};
  if (!floor) {
    placedRecord(record, "CAMERA", black, kEye);
    appendSf(sfText, record, true);
  }
  if (pov && !floor) {
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
  double lightPosition[2][3] = {{200, 300, 300}, {-250, 150, 100}};
  if (floor) {
    // High above the square, one to the right and in front, one to the left
    // and behind, so that shadows fall both ways.
    const double above[2][3] = {{0.3, 0.9, 0.45}, {-0.45, 0.7, -0.25}};
    for (int i = 0; i < 2; ++i) {
      for (int k = 0; k < 3; ++k) lightPosition[i][k] = std::round(above[i][k] * side);
    }
  }
  for (int i = 0; i < 2; ++i) {
    placedRecord(record, "LIGHT", lightColour[i], lightPosition[i]);
    appendSf(sfText, record, false);
    if (pov) appendPov(povText, record);
  }
  if (floor) {
    // The floor: the identity matrix, the plane y = 0.
    const double origin[3] = {0, 0, 0};
    placedRecord(record, "PLANE", kFloorColour, origin);
    appendSf(sfText, record, false);
    if (pov) {
      povText += "plane{y,0 pigment{color rgb";
      appendVector(povText, kFloorColour);
      povText += "}}\n";
    }
  }

  Random random(seed);
  for (std::uint64_t i = 0; i < objects; ++i) {
    if (floor) {
      floorObject(random, side, record);
    } else {
      randomObject(random, record);
    }
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
  std::cout << "sfgen: wrote " << output.string() << " (" << objects << " objects"
            << (floor ? " over a floor plane" : "") << ", " << sf.bytes()
            << " bytes)";
  if (pov) std::cout << " and " << povOutput.string() << " (" << pov->bytes() << " bytes)";
  std::cout << '\n';
  return 0;
}
