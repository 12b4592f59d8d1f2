#include "scene/yaml_reader.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "scene/scene_loader.hpp"

namespace penumbra::scenefile {
namespace {

// yaml-cpp counts lines from 0; people and editors count from 1. A node that is not in the
// document (a missing key) has no position.
int lineOf(const YAML::Node& node) {
  return node.IsDefined() ? node.Mark().line + 1 : 0;
}

// What a node is, in words, for "expected X, got Y" messages.
std::string describe(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a map";
  return "something else";
}

// The 1-based number of the last line, up to `lastLine`, whose indentation (the blanks before its
// first other character) holds a tab; 0 when none does.
int lastTabIndentedLine(const std::string& text, int lastLine) {
  int found = 0, line = 1;
  bool indentation = true;
  for (char c : text) {
    if (line > lastLine) break;
    if (c == '\n') {
      ++line;
      indentation = true;
    } else if (indentation && c == '\t') {
      found = line;
    } else if (c != ' ') {
      indentation = false;
    }
  }
  return found;
}

struct OpenBracket {
  int line = 0;  // 1-based; 0 when none is open
  char bracket = 0;
};

// The innermost '{' or '[' still open at (line, column), both 1-based: where a flow map or list
// that misses its '}' or ']' starts. Quoted text and comments are skipped.
OpenBracket unclosedBracket(const std::string& text, int line, int column) {
  std::vector<OpenBracket> open;  // the brackets open so far
  int at = 1, col = 0;
  char quote = 0;
  bool comment = false;
  char previous = '\n';
  for (char c : text) {
    ++col;
    if (at > line || (at == line && col >= column)) break;
    if (c == '\n') {
      ++at;
      col = 0;
      comment = false;
      quote = 0;  // a quoted scalar that runs over lines is rare in a scene; start afresh
    } else if (comment) {
    } else if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '#' && (previous == ' ' || previous == '\t' || previous == '\n')) {
      comment = true;
    } else if (c == '{' || c == '[') {
      open.push_back({at, c});
    } else if ((c == '}' || c == ']') && !open.empty()) {
      open.pop_back();
    }
    previous = c;
  }
  return open.empty() ? OpenBracket{} : open.back();
}

std::string joined(const std::vector<std::string_view>& words) {
  std::string out;
  for (std::string_view w : words) {
    if (!out.empty()) out += ", ";
    out += w;
  }
  return out;
}

}  // namespace

std::string childKey(const std::string& parent, std::string_view child) {
  return parent.empty() ? std::string(child) : parent + "." + std::string(child);
}

std::string indexKey(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

std::string readInputFile(const std::filesystem::path& file, std::string_view what) {
  std::ifstream in(file);
  if (!in || std::filesystem::is_directory(file)) {
    throw SceneError(file, 0, "", "cannot read " + std::string(what) + " (does it exist?)");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

YAML::Node parseYaml(const std::string& text, const std::filesystem::path& file) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    const int line = e.mark.line + 1;
    // yaml-cpp's words for a tab ("illegal map value", "end of map not found") do not say what
    // is wrong; a tab is the likely cause when one indents a line up to the failing one.
    if (const int tabLine = lastTabIndentedLine(text, line); tabLine > 0) {
      throw SceneError(file, tabLine, "",
                       "this line is indented with a tab, and YAML does not allow tabs in "
                       "indentation: indent with spaces (the YAML parser says: " +
                           e.msg + ")");
    }
    // A flow map or list without its '}' or ']' is noticed on a later line (the next key or list
    // item); the line to fix is the one that opened it.
    if (const OpenBracket open = unclosedBracket(text, line, e.mark.column + 1);
        open.line > 0 && open.line < line) {
      throw SceneError(file, open.line, "",
                       fmt::format("this is not valid YAML: the '{}' opened on this line is not "
                                   "closed with '{}' (the YAML parser says: {})",
                                   open.bracket, open.bracket == '{' ? '}' : ']', e.msg));
    }
    throw SceneError(file, line, "", "this is not valid YAML: " + e.msg);
  }
}

void fail(const std::filesystem::path& file, const Where& where, const std::string& message) {
  throw SceneError(file, where.line, where.key, message);
}

std::string formatNumber(double value) {
  return fmt::format("{}", value);
}

std::string formatVec3(const Vec3& v) {
  return fmt::format("[{}, {}, {}]", v.x(), v.y(), v.z());
}

// ---- MapView

bool MapView::has(std::string_view key) const {
  return find(key).has_value();
}

std::optional<Field> MapView::find(std::string_view key) const {
  for (const Entry& e : entries_) {
    if (e.key == key) return e.value;
  }
  return std::nullopt;
}

Field MapView::require(std::string_view key) const {
  const std::optional<Field> field = find(key);
  if (!field) {
    reader_->fail(Where{where_.line, childKey(where_.key, key)},
                  "missing key '" + std::string(key) + "'");
  }
  if (field->node.IsNull()) reader_->fail(field->where, "'" + std::string(key) + "' has no value");
  return *field;
}

void MapView::allowOnly(const std::vector<std::string_view>& accepted,
                        std::string_view what) const {
  for (const Entry& e : entries_) {
    bool known = false;
    for (std::string_view a : accepted) known = known || e.key == a;
    if (!known) {
      reader_->fail(e.value.where, "unknown key '" + e.key + "'; " + std::string(what) +
                                       " accepts: " + joined(accepted));
    }
  }
}

// ---- Reader

void Reader::fail(const Where& where, const std::string& message) const {
  scenefile::fail(file_, where, message);
}

Field Reader::root(const YAML::Node& node) const {
  return Field{node, Where{lineOf(node), ""}};
}

MapView Reader::map(const Field& field, std::string_view what) const {
  if (!field.node.IsMap()) {
    fail(field.where,
         "expected " + std::string(what) + " as a map (key: value), got " + describe(field.node));
  }
  MapView view;
  view.reader_ = this;
  view.where_ = field.where;
  for (const auto& pair : field.node) {
    const YAML::Node& key = pair.first;
    if (!key.IsScalar()) fail(Where{lineOf(key), field.where.key}, "a key must be a plain name");
    const std::string name = key.Scalar();
    // The key's own line, not the value's: for a block value (a list or map on the following
    // lines, or an empty value) the key's line is where a person looks.
    const Where where{lineOf(key), childKey(field.where.key, name)};
    if (view.has(name)) fail(where, "key '" + name + "' appears twice");
    view.entries_.push_back(MapView::Entry{name, Field{pair.second, where}});
  }
  return view;
}

std::vector<Field> Reader::list(const Field& field, std::string_view what) const {
  if (!field.node.IsSequence()) {
    fail(field.where,
         "expected " + std::string(what) + " as a list [...], got " + describe(field.node));
  }
  std::vector<Field> items;
  for (std::size_t i = 0; i < field.node.size(); ++i) {
    const YAML::Node item = field.node[i];
    items.push_back(Field{item, Where{lineOf(item), indexKey(field.where.key, i)}});
  }
  return items;
}

std::string Reader::text(const Field& field) const {
  if (!field.node.IsScalar() || field.node.Scalar().empty()) {
    fail(field.where, "expected a name, got " + describe(field.node));
  }
  return field.node.Scalar();
}

double Reader::evaluate(const Field& field, const std::string& expression) const {
  const std::string shown = "${" + expression + "}";
  if (expressions_ == nullptr) {
    fail(field.where, "expected a number, got '" + shown +
                          "' (parameter defaults and study files take plain numbers)");
  }
  double value = 0.0;
  try {
    value = expressions_->evaluate(expression);
  } catch (const std::invalid_argument& e) {
    std::string names;
    for (const ParameterValue& p : expressions_->values()) {
      names += (names.empty() ? "" : ", ") + p.name;
    }
    fail(field.where, "cannot evaluate " + shown + ": " + e.what() +
                          (names.empty() ? " (the scene declares no parameters; add "
                                           "'parameters: {name: default}')"
                                         : " (the scene's parameters: " + names + ")"));
  }
  if (!std::isfinite(value)) {
    const ParameterValues used = expressions_->used(expression);
    fail(field.where, shown + " gives " + formatNumber(value) + ", not a finite number" +
                          (used.empty() ? "" : " (with " + describeParameters(used) + ")"));
  }
  evaluated_.push_back(EvaluatedExpression{field.where, expression, value});
  return value;
}

double Reader::number(const Field& field) const {
  if (!field.node.IsScalar()) fail(field.where, "expected a number, got " + describe(field.node));
  if (const std::optional<std::string> expression = expressionText(field.node.Scalar())) {
    return evaluate(field, *expression);
  }
  double value = 0.0;
  try {
    value = field.node.as<double>();
  } catch (const YAML::Exception&) {
    fail(field.where, "expected a number, got " + describe(field.node));
  }
  if (!std::isfinite(value))
    fail(field.where, "expected a finite number, got " + describe(field.node));
  return value;
}

double Reader::nonNegative(const Field& field, std::string_view unit) const {
  const double value = number(field);
  if (value < 0.0) {
    fail(field.where,
         "must not be negative (got " + formatNumber(value) + " " + std::string(unit) + ")");
  }
  return value;
}

double Reader::positive(const Field& field, std::string_view unit) const {
  const double value = number(field);
  if (value <= 0.0) {
    fail(field.where,
         "must be greater than 0 (got " + formatNumber(value) + " " + std::string(unit) + ")");
  }
  return value;
}

std::vector<double> Reader::numbers(const Field& field, std::size_t count) const {
  const std::string expected = "a list of " + std::to_string(count) + " numbers";
  if (!field.node.IsSequence())
    fail(field.where, "expected " + expected + ", got " + describe(field.node));
  if (field.node.size() != count) {
    fail(field.where,
         "expected " + expected + ", got " + std::to_string(field.node.size()) + " numbers");
  }
  std::vector<double> values;
  for (const Field& item : list(field, expected)) values.push_back(number(item));
  return values;
}

Vec3 Reader::vec3(const Field& field) const {
  const std::vector<double> v = numbers(field, 3);
  return Vec3(v[0], v[1], v[2]);
}

Vec3 Reader::direction(const Field& field) const {
  const Vec3 v = vec3(field);
  if (v == Vec3::Zero()) fail(field.where, "a direction cannot be the zero vector");
  return v.stableNormalized();  // normalized() squares: 1e200 would overflow to NaN
}

std::vector<Vec3> Reader::points(const Field& field, std::size_t minimum) const {
  const std::vector<Field> items = list(field, "a list of points [x, y, z]");
  if (items.size() < minimum) {
    fail(field.where, "needs at least " + std::to_string(minimum) + " points [x, y, z], got " +
                          std::to_string(items.size()));
  }
  std::vector<Vec3> out;
  for (const Field& item : items) out.push_back(vec3(item));
  return out;
}

}  // namespace penumbra::scenefile
