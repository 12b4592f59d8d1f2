#include "scene/parameter_reader.hpp"

#include <algorithm>
#include <stdexcept>

namespace penumbra::scenefile {

DeclaredParameters readDeclaredParameters(const Reader& reader, const YAML::Node& document) {
  DeclaredParameters declared;
  declared.where = Where{0, "parameters"};
  if (!document.IsMap()) return declared;
  const std::optional<Field> field =
      reader.map(reader.root(document), "the scene").find("parameters");
  if (!field) return declared;
  declared.where = field->where;
  const MapView map = reader.map(*field, "parameters {name: default value, ...}");
  for (const MapView::Entry& e : map.entries()) {
    if (!isParameterName(e.key)) {
      reader.fail(e.value.where, "'" + e.key +
                                     "' cannot be a parameter name: use letters, digits and _, "
                                     "not starting with a digit (window_width_m)");
    }
    declared.defaults.push_back(ParameterValue{e.key, reader.number(e.value)});
  }
  try {
    const ExpressionEvaluator probe(declared.defaults);  // muparser refuses its own names
  } catch (const std::invalid_argument& e) {
    reader.fail(declared.where, e.what());
  }
  return declared;
}

ParameterValues applyOverrides(const Reader& reader, const DeclaredParameters& declared,
                               const ParameterValues& overrides) {
  ParameterValues values = declared.defaults;
  for (const ParameterValue& o : overrides) {
    const auto it = std::find_if(values.begin(), values.end(),
                                 [&](const ParameterValue& p) { return p.name == o.name; });
    if (it == values.end()) {
      std::string names;
      for (const ParameterValue& p : values) names += (names.empty() ? "" : ", ") + p.name;
      reader.fail(declared.where, "'" + o.name + "' is not a parameter of this scene; " +
                                      (names.empty() ? "it declares none (add 'parameters: {" +
                                                           o.name + ": default}')"
                                                     : "it declares: " + names));
    }
    it->value = o.value;
  }
  return values;
}

}  // namespace penumbra::scenefile
