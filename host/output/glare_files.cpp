#include "output/glare_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <numbers>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "output/result_files.hpp"

namespace penumbra {
namespace {

// +x, −y, ... for the axis directions; [x, y, z] otherwise.
std::string lookLabel(const Vec3& look) {
  const char* axes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (look[i] == 1.0 || look[i] == -1.0)
      return fmt::format("{}{}", look[i] > 0 ? "+" : "-", axes[i]);
  }
  return fmt::format("[{:.3g}, {:.3g}, {:.3g}]", look.x(), look.y(), look.z());
}

std::string optionalNumber(const std::optional<double>& value, const char* format) {
  return value ? fmt::format(fmt::runtime(format), *value) : std::string();
}

double share(const GlareTerm& term, const GlareRating& rating) {
  const double sum = rating.sum();
  return sum > 0.0 ? 100.0 * term.value() / sum : 0.0;
}

std::string limitText(const GlareRating& rating) {
  if (!rating.ugr) return "";
  const std::optional<int> limit = strictestLimitMet(*rating.ugr);
  return limit ? std::to_string(*limit) : "none";
}

// The entries in scene order, each with its observers' ratings.
std::vector<std::pair<std::string, std::vector<const ObserverRating*>>> byEntry(
    const std::vector<ObserverRating>& ratings) {
  std::vector<std::pair<std::string, std::vector<const ObserverRating*>>> entries;
  for (const ObserverRating& rating : ratings) {
    if (entries.empty() || entries.back().first != rating.observer->entry)
      entries.emplace_back(rating.observer->entry, std::vector<const ObserverRating*>{});
    entries.back().second.push_back(&rating);
  }
  return entries;
}

void writeRatingsCsv(std::ostream& out, const std::vector<const ObserverRating*>& ratings,
                     bool interreflection) {
  out << "observer,eye_x_m,eye_y_m,eye_z_m,look_x,look_y,look_z,UGR,UGR_limit_met,UGR_undefined,"
         "L_b_cd_m2,E_ind_lx,sum_L2_omega_over_p2_cd2_m4_sr,sources_rated,"
         "sources_outside_guth_range,luminaires_without_area,strongest_source,"
         "strongest_share_pct\n";
  for (const ObserverRating* rating : ratings) {
    const Observer& o = *rating->observer;
    for (const GlareRating& view : rating->views) {
      const std::string strongest = view.terms.empty() ? "" : view.terms.front().name;
      const std::string strongestShare =
          view.terms.empty() ? "" : fmt::format("{:.1f}", share(view.terms.front(), view));
      out << fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
                         csvField(o.name), o.eye.x(), o.eye.y(), o.eye.z(), view.look.x(),
                         view.look.y(), view.look.z(), optionalNumber(view.ugr, "{:.2f}"),
                         limitText(view), csvField(undefinedReason(view, interreflection)),
                         view.backgroundLuminance, view.backgroundLuminance * std::numbers::pi,
                         view.sum(), view.terms.size(), view.outsideRange, view.withoutArea,
                         csvField(strongest), strongestShare);
    }
  }
}

void writeSourcesCsv(std::ostream& out, const std::vector<const ObserverRating*>& ratings) {
  out << "observer,look_x,look_y,look_z,source,L_cd_m2,omega_sr,omega_far_field_sr,p_guth,"
         "L2_omega_over_p2_cd2_m4_sr,share_pct\n";
  for (const ObserverRating* rating : ratings) {
    for (const GlareRating& view : rating->views) {
      for (const GlareTerm& term : view.terms) {
        out << fmt::format("{},{},{},{},{},{},{},{},{},{},{:.2f}\n",
                           csvField(rating->observer->name), view.look.x(), view.look.y(),
                           view.look.z(), csvField(term.name), term.luminance, term.solidAngle,
                           term.farFieldAngle, term.positionIndex, term.value(), share(term, view));
      }
    }
  }
}

nlohmann::json viewJson(const GlareRating& view, bool interreflection) {
  nlohmann::json sources = nlohmann::json::array();
  for (const GlareTerm& term : view.terms) {
    sources.push_back({{"name", term.name},
                       {"L_cd_m2", term.luminance},
                       {"omega_sr", term.solidAngle},
                       {"omega_far_field_sr", term.farFieldAngle},
                       {"p_guth", term.positionIndex},
                       {"L2_omega_over_p2", term.value()},
                       {"share_pct", share(term, view)}});
  }
  nlohmann::json json{{"look", {view.look.x(), view.look.y(), view.look.z()}},
                      {"UGR", view.ugr ? nlohmann::json(*view.ugr) : nlohmann::json(nullptr)},
                      {"L_b_cd_m2", view.backgroundLuminance},
                      {"E_ind_lx", view.backgroundLuminance * std::numbers::pi},
                      {"sum_L2_omega_over_p2", view.sum()},
                      {"sources_outside_guth_range", view.outsideRange},
                      {"luminaires_without_area", view.withoutArea},
                      {"sources", sources}};
  if (view.ugr) {
    const std::optional<int> limit = strictestLimitMet(*view.ugr);
    json["UGR_limit_met"] = limit ? nlohmann::json(*limit) : nlohmann::json(nullptr);
  } else {
    json["UGR_undefined"] = undefinedReason(view, interreflection);
  }
  return json;
}

nlohmann::json summaryJson(const GlareRun& run) {
  nlohmann::json observers = nlohmann::json::array();
  const std::optional<double> highest = highestUgr(run.ratings);
  for (const ObserverRating& rating : run.ratings) {
    nlohmann::json views = nlohmann::json::array();
    for (const GlareRating& view : rating.views)
      views.push_back(viewJson(view, run.interreflection));
    const std::optional<double> max = rating.ugrMax();
    const Vec3& eye = rating.observer->eye;
    observers.push_back({{"name", rating.observer->name},
                         {"entry", rating.observer->entry},
                         {"eye_m", {eye.x(), eye.y(), eye.z()}},
                         {"UGR_max", max ? nlohmann::json(*max) : nlohmann::json(nullptr)},
                         {"views", views}});
  }
  return {{"penumbra", run.version},
          {"scene", run.sceneFile.string()},
          {"device", run.device},
          {"method", glareMethod()},
          {"background", run.interreflection
                             ? "L_b = E_ind/pi: interreflected illuminance at the eye on the "
                               "plane facing the line of sight"
                             : "direct light only: L_b = 0, UGR undefined"},
          {"UGR_max", highest ? nlohmann::json(*highest) : nlohmann::json(nullptr)},
          {"seconds", run.seconds},
          {"observers", observers}};
}

}  // namespace

std::string glareMethod() {
  return "UGR (CIE 117-1995) = 8 log10(0.25/L_b * sum L^2 omega/p^2): L luminance towards the "
         "eye (cd/m2), omega exact solid angle of the visible luminous area (sr), p Guth "
         "position index (sources above the line of sight, H/R <= 1.9, T/R <= 3), L_b = "
         "E_ind/pi (cd/m2)";
}

std::string undefinedReason(const GlareRating& rating, bool interreflection) {
  if (rating.ugr) return "";
  if (!(rating.backgroundLuminance > 0.0)) {
    return interreflection ? "L_b = 0 (no interreflected light reaches the eye)"
                           : "L_b = 0 (direct light only)";
  }
  return "no glare source within the Guth range";
}

void writeGlareFiles(const GlareRun& run, const std::filesystem::path& directory) {
  std::map<std::string, std::string> stems;  // stem → entry
  for (const auto& group : byEntry(run.ratings)) {
    // Named references, not a structured binding: clang 14 cannot capture those in a lambda.
    const auto& entry = group.first;
    const auto& ratings = group.second;
    const std::string stem = safeFileStem(entry, "observer");
    if (const auto [it, inserted] = stems.emplace(stem, entry); !inserted) {
      throw std::runtime_error(
          fmt::format("observers '{}' and '{}' would share the file {}.csv; "
                      "rename one",
                      it->second, entry, stem));
    }
    writeFile(directory / (stem + ".csv"),
              [&](std::ostream& out) { writeRatingsCsv(out, ratings, run.interreflection); });
    writeFile(directory / (stem + "-sources.csv"),
              [&](std::ostream& out) { writeSourcesCsv(out, ratings); });
  }
  writeFile(directory / "summary.json",
            [&](std::ostream& out) { out << summaryJson(run).dump(2) << "\n"; });
}

std::string glareTable(const GlareRun& run) {
  std::string text = fmt::format("{}\n", glareMethod());
  text += fmt::format("{:<20} {:>22} {:>6} {:>7} {:>12} {:>6} {:>8} {:>6}  {}\n", "Observer",
                      "Eye [m]", "Look", "UGR", "L_b [cd/m²]", "Rated", "Outside", "Limit",
                      "Strongest source (share %)");
  // A grid of observers has many rows: the files hold them all.
  constexpr std::size_t kMaxRows = 60;
  std::size_t rows = 0, total = 0;
  for (const ObserverRating& rating : run.ratings) {
    for (const GlareRating& view : rating.views) {
      ++total;
      if (rows == kMaxRows) continue;
      ++rows;
      const Vec3& eye = rating.observer->eye;
      const std::string strongest = view.terms.empty()
                                        ? "-"
                                        : fmt::format("{} ({:.0f} %)", view.terms.front().name,
                                                      share(view.terms.front(), view));
      text += fmt::format(
          "{:<20} {:>22} {:>6} {:>7} {:>12.4g} {:>6} {:>8} {:>6}  {}\n", rating.observer->name,
          fmt::format("[{:.2f}, {:.2f}, {:.2f}]", eye.x(), eye.y(), eye.z()), lookLabel(view.look),
          view.ugr ? fmt::format("{:.1f}", *view.ugr) : "undef", view.backgroundLuminance,
          view.terms.size(), view.outsideRange, view.ugr ? limitText(view) : "-", strongest);
    }
  }
  if (total > rows) text += fmt::format("... {} more rows in the CSV files\n", total - rows);
  std::vector<std::string> reasons;  // each once, in the order met
  for (const ObserverRating& rating : run.ratings) {
    for (const GlareRating& view : rating.views) {
      const std::string reason = undefinedReason(view, run.interreflection);
      if (!reason.empty() && std::find(reasons.begin(), reasons.end(), reason) == reasons.end())
        reasons.push_back(reason);
    }
  }
  for (const std::string& reason : reasons) text += fmt::format("undef: {}\n", reason);
  return text;
}

}  // namespace penumbra
