#include "tools/sfrender/image_region.h"

#include <CLI/CLI.hpp>
#include <charconv>
#include <vector>

namespace tools {

namespace {

// Whole numbers separated by `separator`, all of the text, or nothing.
std::optional<std::vector<int>> wholeNumbers(const std::string& text, char separator) {
  std::vector<int> numbers;
  const char* at = text.data();
  const char* end = text.data() + text.size();
  while (true) {
    int n = 0;
    if (at < end && *at == '+') ++at;
    auto [next, ec] = std::from_chars(at, end, n);
    if (ec != std::errc() || next == at) return std::nullopt;
    numbers.push_back(n);
    if (next == end) return numbers;
    if (*next != separator) return std::nullopt;
    at = next + 1;
  }
}

std::string regionText(const render::PixelRegion& r) {
  return std::to_string(r.x0) + "," + std::to_string(r.y0) + "," + std::to_string(r.x1) + "," +
         std::to_string(r.y1);
}

}  // namespace

std::optional<render::PixelRegion> parseRegion(const std::string& text) {
  std::optional<std::vector<int>> n = wholeNumbers(text, ',');
  if (!n || n->size() != 4) return std::nullopt;
  return render::PixelRegion{(*n)[0], (*n)[1], (*n)[2], (*n)[3]};
}

std::optional<TileChoice> parseTile(const std::string& text) {
  std::optional<std::vector<int>> n = wholeNumbers(text, '/');
  if (!n || n->size() != 2) return std::nullopt;
  return TileChoice{(*n)[0], (*n)[1]};
}

CLI::Validator regionOption() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        std::optional<render::PixelRegion> r = parseRegion(value);
        if (!r) return "'" + value + "' is not four whole numbers x0,y0,x1,y1";
        if (r->x0 < 0 || r->y0 < 0) return value + " starts outside the image (x0 and y0 below 0)";
        if (r->empty()) return value + " is empty: x1 must be above x0 and y1 above y0";
        return {};
      },
      "", "pixel region");
}

CLI::Validator tileOption() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        std::optional<TileChoice> t = parseTile(value);
        if (!t) return "'" + value + "' is not i/N, tile i (counted from 0) of N";
        if (t->count < 1) return value + " has no tiles: N must be 1 or more";
        if (t->index < 0 || t->index >= t->count) {
          return value + " is not a tile: i must be between 0 and " + std::to_string(t->count - 1);
        }
        return {};
      },
      "", "tile");
}

MaybeFailure regionRefusal(const render::PixelRegion& region, int width, int height) {
  if (region.empty())
    return toolFailure(ExitCode::Usage, "--region: " + regionText(region) + " is empty");
  if (region.x0 < 0 || region.y0 < 0 || region.x1 > width || region.y1 > height) {
    return toolFailure(ExitCode::Usage, "--region: " + regionText(region) +
                                            " reaches outside the image of " +
                                            std::to_string(width) + "x" + std::to_string(height) +
                                            " pixels (x1 at most " + std::to_string(width) +
                                            ", y1 at most " + std::to_string(height) + ")");
  }
  return std::nullopt;
}

MaybeFailure tileRefusal(const TileChoice& tile, int height) {
  if (tile.count > height) {
    return toolFailure(ExitCode::Usage, "--tile: " + std::to_string(tile.count) +
                                            " tiles of whole rows do not fit an image " +
                                            std::to_string(height) + " rows high");
  }
  return std::nullopt;
}

}  // namespace tools
