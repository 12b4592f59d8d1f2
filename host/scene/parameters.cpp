#include "scene/parameters.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>
#include <muParser.h>

namespace penumbra {

bool isParameterName(std::string_view name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front()))) return false;
  for (char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  }
  return true;
}

ParameterValue parseParameterAssignment(std::string_view text) {
  const std::size_t equals = text.find('=');
  const std::string quoted = fmt::format("'{}'", text);
  if (equals == std::string_view::npos) {
    throw std::invalid_argument(quoted + ": expected NAME=VALUE, e.g. window_width_m=1.6");
  }
  const std::string_view name = text.substr(0, equals);
  const std::string_view number = text.substr(equals + 1);
  if (!isParameterName(name)) {
    throw std::invalid_argument(quoted + ": '" + std::string(name) +
                                "' is not a parameter name (letters, digits and _, not starting "
                                "with a digit)");
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (error != std::errc() || end != number.data() + number.size() || !std::isfinite(value)) {
    throw std::invalid_argument(quoted + ": the value '" + std::string(number) +
                                "' is not a finite number");
  }
  return ParameterValue{std::string(name), value};
}

std::string describeParameters(const ParameterValues& values) {
  std::string text;
  for (const ParameterValue& p : values) {
    text += fmt::format("{}{} = {}", text.empty() ? "" : ", ", p.name, p.value);
  }
  return text;
}

namespace scenefile {

std::optional<std::string> expressionText(std::string_view scalar) {
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!scalar.empty() && blank(scalar.front())) scalar.remove_prefix(1);
  while (!scalar.empty() && blank(scalar.back())) scalar.remove_suffix(1);
  if (scalar.size() < 3 || !scalar.starts_with("${") || !scalar.ends_with("}")) return std::nullopt;
  return std::string(scalar.substr(2, scalar.size() - 3));
}

// muparser keeps pointers to the variables: `storage` never reallocates after construction.
struct ExpressionEvaluator::Parser {
  mu::Parser parser;
  std::vector<double> storage;
};

ExpressionEvaluator::ExpressionEvaluator(ParameterValues values)
    : values_(std::move(values)), parser_(std::make_unique<Parser>()) {
  // muparser 2.3.3 defines _pi with 12 digits only; geometry wants every digit.
  parser_->parser.DefineConst("_pi", std::numbers::pi);
  parser_->parser.DefineConst("_e", std::numbers::e);
  parser_->storage.resize(values_.size());
  for (std::size_t i = 0; i < values_.size(); ++i) {
    try {
      parser_->parser.DefineVar(values_[i].name, &parser_->storage[i]);
    } catch (const mu::ParserError& e) {
      throw std::invalid_argument("'" + values_[i].name +
                                  "' cannot be a parameter name: " + e.GetMsg());
    }
  }
}

ExpressionEvaluator::~ExpressionEvaluator() = default;

double ExpressionEvaluator::evaluate(const std::string& expression) const {
  // Reset before each evaluation: muparser's '=' operator could otherwise change a parameter for
  // every later field.
  for (std::size_t i = 0; i < values_.size(); ++i) parser_->storage[i] = values_[i].value;
  try {
    parser_->parser.SetExpr(expression);
    const double value = parser_->parser.Eval();
    if (parser_->parser.GetNumResults() != 1) {
      throw std::invalid_argument("an expression gives one number; this one gives " +
                                  std::to_string(parser_->parser.GetNumResults()));
    }
    return value;
  } catch (const mu::ParserError& e) {
    throw std::invalid_argument(e.GetMsg());
  }
}

ParameterValues ExpressionEvaluator::used(const std::string& expression) const {
  ParameterValues used;
  try {
    parser_->parser.SetExpr(expression);
    const mu::varmap_type& names = parser_->parser.GetUsedVar();
    for (const ParameterValue& p : values_) {
      if (names.count(p.name) != 0) used.push_back(p);
    }
  } catch (const mu::ParserError&) {
    // An invalid expression uses nothing that can be named; evaluate() reports it.
  }
  return used;
}

}  // namespace scenefile
}  // namespace penumbra
