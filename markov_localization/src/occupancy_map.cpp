#include "markov_localization/occupancy_map.h"

#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>

#include "spott_map/yaml_reader.h"

namespace markov_localization {

using spott_map::SourceError;
using spott_map::SourceLocation;

std::vector<std::string> ValidateOccupancyMap(const OccupancyMap& m) {
  std::vector<std::string> errors;
  if (m.width <= 0 || m.height <= 0) errors.push_back("width and height must be positive");
  if (m.width > 100000 || m.height > 100000) errors.push_back("width and height must be <= 100000");
  if (!(m.resolution_m > 0.0 && m.resolution_m <= 10.0))
    errors.push_back("resolution must be in (0, 10] m");
  if (!m.origin.allFinite() || !std::isfinite(m.origin_yaw))
    errors.push_back("origin must be finite");
  if (m.width > 0 && m.height > 0 && m.width <= 100000 && m.height <= 100000 &&
      m.data.size() != static_cast<std::size_t>(m.width) * static_cast<std::size_t>(m.height))
    errors.push_back("data has " + std::to_string(m.data.size()) + " cells, width * height is " +
                     std::to_string(static_cast<long long>(m.width) * m.height));
  for (std::int8_t v : m.data) {
    if (v < -1 || v > 100) {
      errors.push_back("data holds " + std::to_string(v) + " (values are 0..100 or -1 unknown)");
      break;
    }
  }
  return errors;
}

namespace {

// Skips whitespace and '#' comments of a PGM header.
void SkipSpace(const std::string& b, std::size_t& i) {
  while (i < b.size()) {
    if (b[i] == '#') {
      while (i < b.size() && b[i] != '\n') ++i;
    } else if (std::isspace(static_cast<unsigned char>(b[i]))) {
      ++i;
    } else {
      break;
    }
  }
}

bool ReadInt(const std::string& b, std::size_t& i, long* out) {
  SkipSpace(b, i);
  if (i >= b.size() || !std::isdigit(static_cast<unsigned char>(b[i]))) return false;
  long v = 0;
  while (i < b.size() && std::isdigit(static_cast<unsigned char>(b[i]))) {
    v = v * 10 + (b[i] - '0');
    if (v > 1000000000L) return false;
    ++i;
  }
  *out = v;
  return true;
}

bool ReadFile(const std::string& path, std::string* bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  bytes->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

std::string Directory(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

bool EndsWith(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i])
      return false;
  return true;
}

}  // namespace

std::optional<std::vector<std::uint8_t>> DecodePgm(const std::string& b, const std::string& file,
                                                   int* width, int* height,
                                                   std::vector<SourceError>* errors) {
  auto fail = [&](std::size_t at, const std::string& message) {
    errors->push_back(
        SourceError{SourceLocation{file, 0, 0}, "byte " + std::to_string(at) + ": " + message});
    return std::nullopt;
  };
  if (b.size() < 2 || b[0] != 'P' || (b[1] != '5' && b[1] != '2'))
    return fail(0, "not a PGM image (expected the magic number P5 or P2)");
  const bool binary = b[1] == '5';
  std::size_t i = 2;
  long w = 0, h = 0, maxval = 0;
  if (!ReadInt(b, i, &w) || !ReadInt(b, i, &h) || !ReadInt(b, i, &maxval))
    return fail(i, "PGM header: expected width, height and maximum value");
  if (w <= 0 || h <= 0 || w > 100000 || h > 100000 || w * h > 400000000L)
    return fail(i, "PGM size " + std::to_string(w) + " x " + std::to_string(h) +
                       " out of range (1..100000 each, at most 4e8 pixels)");
  if (maxval <= 0 || maxval > 255)
    return fail(i, "PGM maximum value " + std::to_string(maxval) +
                       " is not supported (8-bit images only: 1..255)");
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  std::vector<std::uint8_t> pixels(n);
  if (binary) {
    // Exactly one whitespace byte separates the header from the raster.
    if (i >= b.size() || !std::isspace(static_cast<unsigned char>(b[i])))
      return fail(i, "PGM header must end with one whitespace byte");
    ++i;
    if (b.size() - i < n)
      return fail(b.size(), "PGM raster is truncated: " + std::to_string(b.size() - i) + " of " +
                                std::to_string(n) + " bytes");
    for (std::size_t k = 0; k < n; ++k) pixels[k] = static_cast<std::uint8_t>(b[i + k]);
  } else {
    for (std::size_t k = 0; k < n; ++k) {
      long v = 0;
      if (!ReadInt(b, i, &v))
        return fail(i, "PGM (P2) expected pixel " + std::to_string(k) + " of " + std::to_string(n));
      if (v > maxval) return fail(i, "PGM pixel value above the maximum value");
      pixels[k] = static_cast<std::uint8_t>(v);
    }
  }
  // Scale to 0..255 like an 8-bit image (map_server reads the pixel as a fraction of white).
  if (maxval != 255)
    for (auto& p : pixels) p = static_cast<std::uint8_t>(std::lround(255.0 * p / maxval));
  *width = static_cast<int>(w);
  *height = static_cast<int>(h);
  return pixels;
}

MapFileResult ParseMapServerMap(const std::string& yaml_text, const std::string& file,
                                bool (*read_file)(const std::string& path, std::string* bytes)) {
  MapFileResult result;
  spott_map::YamlReader r(file);
  const YAML::Node root = r.Parse(yaml_text);
  const std::string what = "map_server map";
  if (!r.errors().empty() || !root) {
    if (r.errors().empty()) r.Error(SourceLocation{file, 1, 1}, what + ": the file is empty");
    result.errors = r.errors();
    return result;
  }
  if (!r.ExpectMap(
          root, what,
          {"image", "resolution", "origin", "negate", "occupied_thresh", "free_thresh", "mode"})) {
    result.errors = r.errors();
    return result;
  }
  const auto image = r.String(root, "image", what, true);
  const auto resolution =
      r.Number(root, "resolution", what, true, spott_map::NumberRule::kPositive);
  const auto origin = r.Pose(root, "origin", what, true);
  const auto negate = r.Number(root, "negate", what, true);
  const auto occ = r.Number(root, "occupied_thresh", what, true);
  const auto free = r.Number(root, "free_thresh", what, true);
  const auto mode = r.String(root, "mode", what, false);
  if (negate && *negate != 0.0 && *negate != 1.0)
    r.Error(root["negate"], what + ": negate must be 0 or 1");
  if (occ && !(*occ > 0.0 && *occ <= 1.0))
    r.Error(root["occupied_thresh"], what + ": occupied_thresh must be in (0, 1]");
  if (free && !(*free >= 0.0 && *free < 1.0))
    r.Error(root["free_thresh"], what + ": free_thresh must be in [0, 1)");
  if (occ && free && *free >= *occ)
    r.Error(root["free_thresh"], what + ": free_thresh must be below occupied_thresh");
  if (resolution && *resolution > 10.0)
    r.Error(root["resolution"], what + ": resolution must be at most 10 m per pixel");
  if (mode && *mode != "trinary" && *mode != "scale" && *mode != "raw")
    r.Error(root["mode"], what + ": mode must be trinary, scale or raw, got '" + *mode + "'");
  if (image && !EndsWith(*image, ".pgm"))
    r.Error(root["image"], what + ": image '" + *image +
                               "': only PGM images are read (map_saver writes PGM; convert "
                               "others, e.g. with `convert map.png map.pgm`)");
  if (!r.errors().empty() || !image || !resolution || !origin || !negate || !occ || !free) {
    result.errors = r.errors();
    return result;
  }
  const std::string path = (*image)[0] == '/' ? *image : Directory(file) + "/" + *image;
  std::string bytes;
  if (!read_file(path, &bytes)) {
    r.Error(root["image"], what + ": cannot read the image " + path);
    result.errors = r.errors();
    return result;
  }
  int w = 0, h = 0;
  std::vector<SourceError> image_errors;
  const auto pixels = DecodePgm(bytes, path, &w, &h, &image_errors);
  if (!pixels) {
    result.errors = image_errors;
    return result;
  }
  OccupancyMap m;
  m.origin = origin->Position();
  m.origin_yaw = origin->yaw;
  m.resolution_m = *resolution;
  m.width = w;
  m.height = h;
  m.data.resize(pixels->size());
  const std::string md = mode.value_or("trinary");
  for (int row = 0; row < h; ++row) {
    for (int x = 0; x < w; ++x) {
      int p = (*pixels)[static_cast<std::size_t>(row) * w + x];
      if (*negate != 0.0) p = 255 - p;
      std::int8_t value;
      if (md == "raw") {
        value = static_cast<std::int8_t>(p <= 100 ? p : -1);
      } else {
        const double o = (255.0 - p) / 255.0;
        if (o > *occ)
          value = 100;
        else if (o < *free)
          value = 0;
        else if (md == "trinary")
          value = -1;
        else
          value = static_cast<std::int8_t>(1 + std::lround(98.0 * (o - *free) / (*occ - *free)));
      }
      // The image's first row is the top of the map.
      m.data[static_cast<std::size_t>(h - 1 - row) * w + x] = value;
    }
  }
  result.map = std::move(m);
  return result;
}

MapFileResult LoadMapServerMap(const std::string& yaml_path) {
  std::string text;
  if (!ReadFile(yaml_path, &text)) {
    MapFileResult result;
    result.errors.push_back(
        SourceError{SourceLocation{yaml_path, 0, 0}, "cannot read the map file"});
    return result;
  }
  return ParseMapServerMap(text, yaml_path, &ReadFile);
}

bool WriteMapServerMap(const OccupancyMap& map, const std::string& yaml_path,
                       const std::string& image_name, std::string* error) {
  const auto problems = ValidateOccupancyMap(map);
  if (!problems.empty()) {
    *error = problems.front();
    return false;
  }
  const std::string image_path = Directory(yaml_path) + "/" + image_name;
  std::ofstream img(image_path, std::ios::binary);
  if (!img) {
    *error = "cannot write " + image_path;
    return false;
  }
  img << "P5\n# markov_localization WriteMapServerMap\n"
      << map.width << " " << map.height << "\n255\n";
  for (int row = 0; row < map.height; ++row) {
    const int j = map.height - 1 - row;
    for (int i = 0; i < map.width; ++i) {
      const int v = map.at(i, j);
      const unsigned char p = v >= 65 ? 0 : (v >= 0 && v < 20 ? 254 : 205);
      img.put(static_cast<char>(p));
    }
  }
  std::ofstream yaml(yaml_path);
  if (!yaml || !img) {
    *error = "cannot write " + (yaml ? image_path : yaml_path);
    return false;
  }
  yaml.precision(10);
  yaml << "image: " << image_name << "\nresolution: " << map.resolution_m << "\norigin: ["
       << map.origin.x() << ", " << map.origin.y() << ", " << map.origin_yaw
       << "]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  return static_cast<bool>(yaml);
}

}  // namespace markov_localization
