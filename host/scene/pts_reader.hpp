#pragma once
// Radiance sensor point files (.pts, as read by rtrace -I): one point per line,
// "x y z nx ny nz" separated by white space. Blank lines and lines starting with '#' are skipped.
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/vec.hpp"

namespace penumbra::scenefile {

struct SensorPoints {
  std::vector<Vec3> positions;  // m
  std::vector<Vec3> normals;    // unit
};

// Parses the text of a .pts file; errors are SceneErrors naming `file`, the line and `key`
// (the grid's key path in the scene, e.g. grids[3].points).
SensorPoints parsePts(const std::string& text, const std::filesystem::path& file,
                      const std::string& key);

// Reads `file`; a file that cannot be read is a SceneError reported at `sceneFile`:`sceneLine`.
SensorPoints readPts(const std::filesystem::path& file, const std::filesystem::path& sceneFile,
                     int sceneLine, const std::string& key);

}  // namespace penumbra::scenefile
