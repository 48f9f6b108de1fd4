// Occupancy grid maps as ROS users have them, without ROS: the content of a
// nav_msgs/OccupancyGrid (from a /map topic) and map_server's file format (a YAML file naming a
// PGM image), read and written here. Conventions (nav_msgs/MapMetaData, map_server):
// - cell (i, j) covers [origin.x + i res, origin.x + (i + 1) res) x [origin.y + j res, ...):
//   `origin` is the lower-left CORNER of cell (0, 0) (its centre is half a cell further), and
//   the grid is rotated by origin_yaw about that corner;
// - data is row-major with row 0 at the bottom (smallest y); values 0..100 are occupancy
//   percentages, -1 unknown;
// - a map_server image's first row is the TOP of the map; pixel p (0 black .. 255 white) is
//   occupancy (255 - p) / 255 (negate 0), occupied above occupied_thresh, free below
//   free_thresh, unknown between (mode trinary; scale: 0..100 in between; raw: the pixel value).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "spott_map/geometry.h"
#include "spott_map/source_location.h"

namespace markov_localization {

struct OccupancyMap {
  spott_map::Vec2 origin{0.0, 0.0};  ///< Lower-left corner of cell (0, 0) (m, map frame).
  double origin_yaw = 0.0;           ///< Rotation of the grid about `origin` (rad); MapModel
                                     ///< refuses anything but 0.
  double resolution_m = 0.05;        ///< Cell side (m).
  int width = 0;
  int height = 0;
  std::vector<std::int8_t> data;  ///< width * height, row 0 at the bottom; 0..100 or -1.

  std::int8_t at(int i, int j) const {
    return data[static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(i)];
  }
};

/// Every problem of a map's metadata and data (size, resolution, values), empty when usable.
std::vector<std::string> ValidateOccupancyMap(const OccupancyMap& map);

struct MapFileResult {
  std::optional<OccupancyMap> map;
  std::vector<spott_map::SourceError> errors;  ///< file:line:column: what is wrong
  bool ok() const { return map.has_value() && errors.empty(); }
};

/// map_server's YAML (image, resolution, origin [x, y, yaw], negate, occupied_thresh,
/// free_thresh, optional mode trinary|scale|raw) and the binary (P5) or text (P2) PGM it
/// names, relative to the YAML's directory. `yaml_text` is the YAML file's content, `file` its
/// path (for errors and the image's directory); `read_file` reads the image (returns false when
/// it cannot). Other image formats are refused with a message saying so.
MapFileResult ParseMapServerMap(const std::string& yaml_text, const std::string& file,
                                bool (*read_file)(const std::string& path, std::string* bytes));
/// Reads `yaml_path` and its image from disk.
MapFileResult LoadMapServerMap(const std::string& yaml_path);

/// Decodes a PGM (P5 with maxval <= 255, or P2) into pixels, first row first. Errors name
/// `file` and the byte offset.
std::optional<std::vector<std::uint8_t>> DecodePgm(const std::string& bytes,
                                                   const std::string& file, int* width, int* height,
                                                   std::vector<spott_map::SourceError>* errors);

/// Writes `map` as map_server would (map_saver): `yaml_path` and a P5 PGM `image_name` in the
/// same directory; occupied (>= 65) black, free (< 20) white 254, unknown 205. False with
/// `error` when a file cannot be written.
bool WriteMapServerMap(const OccupancyMap& map, const std::string& yaml_path,
                       const std::string& image_name, std::string* error);

}  // namespace markov_localization
