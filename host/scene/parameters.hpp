#pragma once
// Scene parameters: a scene declares `parameters: {window_width_m: 2.0, ...}` with defaults, and
// any numeric field may then be an expression in them, written "${3.0 - window_width_m/2}".
// A sweep (host/study) loads the same scene file once per case with other values; a scene with
// parameters still loads alone with its defaults.
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra {

struct ParameterValue {
  std::string name;
  double value = 0.0;
  bool operator==(const ParameterValue&) const = default;
};
// In the order the scene (or the study) declares them.
using ParameterValues = std::vector<ParameterValue>;

// "name=value" (as given to `penumbra grid --set`) → its parts. Throws std::invalid_argument with
// a message naming the text when it is not a valid name, an '=' and a finite number.
ParameterValue parseParameterAssignment(std::string_view text);

// Whether `name` can be a parameter: a letter or '_' and then letters, digits or '_' (what an
// expression can refer to).
bool isParameterName(std::string_view name);

// "name = value, name = value": how messages and the progress line show a case's values.
std::string describeParameters(const ParameterValues& values);

namespace scenefile {

// The expression inside "${...}" (blanks around it allowed), or nothing when `scalar` is plain
// text.
std::optional<std::string> expressionText(std::string_view scalar);

// Evaluates expressions (muparser syntax: + - * / ^, comparisons, `a ? b : c`, sin, sqrt, min,
// max, _pi, ...) over fixed parameter values. Expressions cannot change the values (each
// evaluation starts from them again).
class ExpressionEvaluator {
 public:
  // Throws std::invalid_argument when muparser refuses a name (one of its own functions).
  explicit ExpressionEvaluator(ParameterValues values);
  ~ExpressionEvaluator();
  ExpressionEvaluator(const ExpressionEvaluator&) = delete;
  ExpressionEvaluator& operator=(const ExpressionEvaluator&) = delete;

  const ParameterValues& values() const { return values_; }
  // Throws std::invalid_argument with a message for a person when the expression is not valid.
  double evaluate(const std::string& expression) const;
  // The parameters `expression` refers to, in declaration order.
  ParameterValues used(const std::string& expression) const;

 private:
  struct Parser;
  ParameterValues values_;
  std::unique_ptr<Parser> parser_;
};

}  // namespace scenefile
}  // namespace penumbra
