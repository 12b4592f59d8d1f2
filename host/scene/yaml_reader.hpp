#pragma once
// Line-aware reading of YAML values. Every value read from a scene carries where it came from
// (1-based line and key path such as `sources[1].flux`) so that every SceneError can send a
// lighting designer to the exact spot in their file, and every type or range mistake is reported
// in the same words wherever it happens.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "geometry/vec.hpp"
#include "scene/parameters.hpp"

namespace penumbra::scenefile {

// Where a value is in the scene file: line (1-based, 0 when unknown) and key path.
struct Where {
  int line = 0;
  std::string key;
};

std::string childKey(const std::string& parent, std::string_view child);  // "a" + "b" → "a.b"
std::string indexKey(const std::string& parent, std::size_t index);       // "a" + 3 → "a[3]"

// The text of `file`; one that cannot be read is a SceneError naming it as `what` ("the scene
// file").
std::string readInputFile(const std::filesystem::path& file, std::string_view what);
// The YAML document in `text`; invalid YAML is a SceneError at its line.
YAML::Node parseYaml(const std::string& text, const std::filesystem::path& file);

// Throws the SceneError for `where` in `file`.
[[noreturn]] void fail(const std::filesystem::path& file, const Where& where,
                       const std::string& message);

// A YAML value and where it is.
struct Field {
  YAML::Node node;
  Where where;
};

class Reader;

// A YAML map already checked to be one, with unique scalar keys, in file order.
class MapView {
 public:
  struct Entry {
    std::string key;
    Field value;
  };

  bool has(std::string_view key) const;
  std::optional<Field> find(std::string_view key) const;
  // The value of `key`; a missing (or empty) one is an error at the map's line.
  Field require(std::string_view key) const;
  // Every key must be one of `accepted`; the error lists them, introduced by `what` ("a source").
  void allowOnly(const std::vector<std::string_view>& accepted, std::string_view what) const;

  const Where& where() const { return where_; }
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  friend class Reader;
  const Reader* reader_ = nullptr;
  Where where_;
  std::vector<Entry> entries_;
};

// A number written as "${expression}" and what it gave, kept so that a later error about the
// value (a window that no longer fits its wall) can show the expression behind it.
struct EvaluatedExpression {
  Where where;
  std::string expression;
  double value = 0.0;
};

// Reads typed values out of Fields; every mistake becomes a SceneError naming `file`.
class Reader {
 public:
  // Without `expressions`, "${...}" is not a number (study files, parameter defaults).
  explicit Reader(std::filesystem::path file, const ExpressionEvaluator* expressions = nullptr)
      : file_(std::move(file)), expressions_(expressions) {}

  const std::filesystem::path& file() const { return file_; }
  [[noreturn]] void fail(const Where& where, const std::string& message) const;

  // The document's root, at its first line, with an empty key path.
  Field root(const YAML::Node& node) const;

  // `what` names the expected thing for the message ("a source", "the room").
  MapView map(const Field& field, std::string_view what) const;
  std::vector<Field> list(const Field& field, std::string_view what) const;

  std::string text(const Field& field) const;
  double number(const Field& field) const;  // finite; "${expression}" is evaluated
  double nonNegative(const Field& field, std::string_view unit) const;
  double positive(const Field& field, std::string_view unit) const;
  std::vector<double> numbers(const Field& field, std::size_t count) const;
  Vec3 vec3(const Field& field) const;
  Vec3 direction(const Field& field) const;  // unit; a zero vector is an error
  // A list of at least `minimum` points [x, y, z].
  std::vector<Vec3> points(const Field& field, std::size_t minimum) const;

  const ExpressionEvaluator* expressions() const { return expressions_; }
  // Every expression number() has evaluated so far, in reading order.
  const std::vector<EvaluatedExpression>& evaluated() const { return evaluated_; }

 private:
  double evaluate(const Field& field, const std::string& expression) const;

  std::filesystem::path file_;
  const ExpressionEvaluator* expressions_ = nullptr;
  // A record for messages, not state the reading depends on; hence mutable in a const reader.
  mutable std::vector<EvaluatedExpression> evaluated_;
};

// Formats a number for a message: the shortest form that reads back the same (0.2, 3400).
std::string formatNumber(double value);
std::string formatVec3(const Vec3& v);  // [x, y, z]

}  // namespace penumbra::scenefile
