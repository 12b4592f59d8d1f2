#include "scene/pts_reader.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "scene/yaml_reader.hpp"

namespace penumbra::scenefile {

SensorPoints parsePts(const std::string& text, const std::filesystem::path& file,
                      const std::string& key) {
  SensorPoints out;
  std::istringstream lines(text);
  std::string line;
  int lineNumber = 0;
  while (std::getline(lines, line)) {
    ++lineNumber;
    std::istringstream firstWord(line);
    std::string first;
    if (!(firstWord >> first) || first.front() == '#') continue;

    const Where where{lineNumber, key};
    double v[6];
    int count = 0;
    std::istringstream words(line);
    std::string word;
    while (words >> word) {
      if (count == 6) fail(file, where, "expected 6 numbers (x y z nx ny nz), got more");
      // std::stod accepts "1.5abc" after reading 1.5; a sensor file with such a word is broken.
      std::size_t used = 0;
      try {
        v[count] = std::stod(word, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != word.size() || !std::isfinite(v[count])) {
        fail(file, where, "expected a number, got '" + word + "'");
      }
      ++count;
    }
    if (count != 6) {
      fail(file, where, "expected 6 numbers (x y z nx ny nz), got " + std::to_string(count));
    }
    const Vec3 normal(v[3], v[4], v[5]);
    if (normal == Vec3::Zero()) fail(file, where, "the normal (nx ny nz) is the zero vector");
    out.positions.emplace_back(v[0], v[1], v[2]);
    // Stable: normalized() squares the components, and a normal of 1e200 overflows to a NaN one.
    out.normals.push_back(normal.stableNormalized());
  }
  return out;
}

SensorPoints readPts(const std::filesystem::path& file, const std::filesystem::path& sceneFile,
                     int sceneLine, const std::string& key) {
  std::ifstream in(file);
  if (!in || std::filesystem::is_directory(file)) {
    fail(sceneFile, Where{sceneLine, key}, "cannot read the points file " + file.string());
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parsePts(text.str(), file, key);
}

}  // namespace penumbra::scenefile
