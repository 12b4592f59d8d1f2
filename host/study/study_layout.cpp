#include "study/study_layout.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "output/json_number.hpp"

namespace penumbra {
namespace {

// Ordered both ways: parameters keep the study's order in the files and when read back.
using Json = nlohmann::ordered_json;
using OrderedJson = nlohmann::ordered_json;

OrderedJson valuesJson(const ParameterValues& values) {
  OrderedJson object = OrderedJson::object();
  for (const ParameterValue& p : values) object[p.name] = p.value;
  return object;
}

// Values in the order of `names`.
ParameterValues valuesFrom(const Json& json, const std::vector<std::string>& names) {
  ParameterValues values;
  for (const std::string& name : names) values.push_back({name, json.at(name).get<double>()});
  return values;
}

template <typename Parse>
auto parsing(const std::filesystem::path& file, Parse parse) {
  try {
    return parse();
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": not a file penumbra wrote (" + e.what() + ")");
  }
}

std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

bool StudyLayout::sameStudy(const StudyLayout& other) const {
  if (parameters != other.parameters || combination != other.combination || grids != other.grids ||
      metrics != other.metrics || caseOutputs != other.caseOutputs || charts != other.charts ||
      cases.size() != other.cases.size()) {
    return false;
  }
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (cases[i].id != other.cases[i].id || cases[i].values != other.cases[i].values ||
        cases[i].fingerprint != other.cases[i].fingerprint) {
      return false;
    }
  }
  return true;
}

OrderedJson layoutJson(const StudyLayout& layout) {
  OrderedJson metrics = OrderedJson::array();
  for (StudyMetric m : layout.metrics) metrics.push_back(std::string(metricInfo(m).name));
  OrderedJson cases = OrderedJson::array();
  for (const PlannedCase& c : layout.cases) {
    cases.push_back(
        {{"id", c.id}, {"parameters", valuesJson(c.values)}, {"fingerprint", c.fingerprint}});
  }
  return {
      {"study", layout.studyFile},
      {"scene", layout.sceneFile},
      {"parameters", layout.parameters},
      {"combination", layout.combination == Combination::Grid ? "grid" : "zip"},
      {"grids", layout.grids},
      {"metrics", metrics},
      {"case_outputs", layout.caseOutputs},
      {"charts", layout.charts},
      {"cases", cases},
  };
}

StudyLayout layoutFromJson(const Json& json, const std::filesystem::path& file) {
  return parsing(file, [&] {
    StudyLayout layout;
    layout.studyFile = json.at("study").get<std::string>();
    layout.sceneFile = json.at("scene").get<std::string>();
    layout.parameters = json.at("parameters").get<std::vector<std::string>>();
    layout.combination =
        json.at("combination").get<std::string>() == "zip" ? Combination::Zip : Combination::Grid;
    layout.grids = json.at("grids").get<std::vector<std::string>>();
    for (const Json& name : json.at("metrics")) {
      const std::optional<StudyMetric> metric = metricNamed(name.get<std::string>());
      if (!metric) throw std::runtime_error(file.string() + ": unknown metric " + name.dump());
      layout.metrics.push_back(*metric);
    }
    layout.caseOutputs = json.at("case_outputs").get<std::vector<std::string>>();
    layout.charts = json.at("charts").get<bool>();
    for (const Json& c : json.at("cases")) {
      layout.cases.push_back(PlannedCase{c.at("id").get<std::string>(),
                                         valuesFrom(c.at("parameters"), layout.parameters),
                                         c.at("fingerprint").get<std::string>()});
    }
    return layout;
  });
}

OrderedJson caseJson(const CaseRecord& record) {
  OrderedJson grids = OrderedJson::array();
  for (const CaseGridResult& g : record.grids) {
    OrderedJson grid = {{"name", g.name},
                        {"points", g.metrics.points},
                        {"points_inside_solids", g.metrics.pointsInsideSolids},
                        {"spacing_m", jsonNumber<OrderedJson>(g.metrics.spacing)}};
    for (const StudyMetricInfo& m : studyMetrics()) {
      grid[std::string(m.column)] = jsonNumber<OrderedJson>(metricValue(g, m.metric));
    }
    grids.push_back(grid);
  }
  OrderedJson json = {{"id", record.id},
                      {"fingerprint", record.fingerprint},
                      {"parameters", valuesJson(record.values)},
                      {"grids", grids},
                      {"images", record.images}};
  if (record.rated) json["UGR_max"] = record.ugrMax ? OrderedJson(*record.ugrMax) : OrderedJson();
  return json;
}

CaseRecord caseRecordFromJson(const Json& json, const std::filesystem::path& file) {
  return parsing(file, [&] {
    CaseRecord record;
    record.id = json.at("id").get<std::string>();
    record.fingerprint = json.at("fingerprint").get<std::string>();
    std::vector<std::string> names;
    for (const auto& item : json.at("parameters").items()) names.push_back(item.key());
    record.values = valuesFrom(json.at("parameters"), names);
    for (const Json& g : json.at("grids")) {
      CaseGridResult grid;
      grid.name = g.at("name").get<std::string>();
      grid.metrics.points = g.at("points").get<std::size_t>();
      grid.metrics.pointsInsideSolids = g.at("points_inside_solids").get<std::size_t>();
      grid.metrics.spacing = numberFromJson(g.at("spacing_m"));
      grid.metrics.eAvg = numberFromJson(g.at("Eavg_lx"));
      grid.metrics.eMin = numberFromJson(g.at("Emin_lx"));
      grid.metrics.eMax = numberFromJson(g.at("Emax_lx"));
      grid.metrics.u0 = numberFromJson(g.at("U0"));
      grid.metrics.ud = numberFromJson(g.at("Ud"));
      // The daylight and sun columns are written for every grid (null without a sky or a sun); a
      // record without one reads it as NaN.
      const auto optionalColumn = [&](StudyMetric m) {
        const auto it = g.find(std::string(metricInfo(m).column));
        return it == g.end() ? std::numeric_limits<double>::quiet_NaN() : numberFromJson(*it);
      };
      grid.daylight.mean = optionalColumn(StudyMetric::DFavg);
      grid.daylight.min = optionalColumn(StudyMetric::DFmin);
      grid.daylight.median = optionalColumn(StudyMetric::DFmedian);
      grid.daylight.sky = optionalColumn(StudyMetric::SCavg);
      grid.daylight.externallyReflected = optionalColumn(StudyMetric::ERCavg);
      grid.daylight.internallyReflected = optionalColumn(StudyMetric::IRCavg);
      grid.daylight.level = optionalColumn(StudyMetric::EN17037);
      grid.sun.eAvg = optionalColumn(StudyMetric::EsunAvg);
      grid.sun.eMax = optionalColumn(StudyMetric::EsunMax);
      grid.sun.sunlitShare = optionalColumn(StudyMetric::SunlitShare);
      record.grids.push_back(grid);
    }
    record.images = json.at("images").get<std::vector<std::string>>();
    if (const auto ugr = json.find("UGR_max"); ugr != json.end()) {
      record.rated = true;
      if (!ugr->is_null()) record.ugrMax = ugr->get<double>();
    }
    return record;
  });
}

std::optional<StudyLayout> readLayout(const std::filesystem::path& out) {
  const std::filesystem::path file = out / kStudyJson;
  if (!std::filesystem::exists(file)) return std::nullopt;
  const std::string text = readText(file);
  return parsing(file, [&] { return layoutFromJson(Json::parse(text), file); });
}

std::optional<CaseRecord> readFinishedCase(const std::filesystem::path& out,
                                           const PlannedCase& planned) {
  const std::filesystem::path file = out / kCasesFolder / planned.id / kCaseJson;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return std::nullopt;
  try {
    const CaseRecord record = caseRecordFromJson(Json::parse(readText(file)), file);
    if (record.id != planned.id || record.fingerprint != planned.fingerprint) return std::nullopt;
    return record;
  } catch (const std::exception&) {
    return std::nullopt;  // unreadable: computed again
  }
}

}  // namespace penumbra
