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

// A table value: candela (or cd/klm) must be finite and not negative. `where` names the angles,
// e.g. "C 45°, γ 10°".
void checkIntensity(double value, int line, const std::filesystem::path& file,
                    const std::string& field, const std::string& where);

}  // namespace penumbra::photometry
