#pragma once
// Checks shared by the IES and EULUMDAT readers on the numbers a file gives, each error naming
// the line of the offending value.
#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::photometry {

// Values as read, each with its 1-based line.
struct NumberedValues {
  std::vector<double> values;
  std::vector<int> lines;
};

// Every angle in [minDeg, maxDeg] and each larger than the one before; PhotometricError at the
// first that is not.
void checkAngles(const NumberedValues& angles, const std::filesystem::path& file,
                 const std::string& field, double minDeg, double maxDeg);

// `value` as a whole number in [min, max] ("37" or "37.0"); `meaning` says what the numbers
// stand for ("1 = C, 2 = B, 3 = A"), or why the limit ("at most 1801").
int wholeNumber(double value, int min, int max, const std::string& meaning,
                const std::filesystem::path& file, int line, const std::string& field);

// The largest intensity read (cd): far above any luminaire (a searchlight reaches 10^9 cd), low
// enough that every sum over a table stays finite.
inline constexpr double kMaxCandela = 1e12;

// A table value in cd: `value` as the file gives it (cd, or cd/klm) must be finite and not
// negative, and `value` x `factor` (the multipliers, or the lamps' klm) at most kMaxCandela.
// `where` names the angles, e.g. "vertical angle 10°".
double candelaOf(double value, double factor, int line, const std::filesystem::path& file,
                 const std::string& field, const std::string& where);

}  // namespace penumbra::photometry
