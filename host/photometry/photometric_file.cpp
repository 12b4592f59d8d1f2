#include "photometry/photometric_file.hpp"

#include <cctype>

#include "photometry/ies_reader.hpp"
#include "photometry/ldt_reader.hpp"
#include "photometry/photometric_error.hpp"
#include "photometry/photometric_text.hpp"

namespace penumbra::photometry {

PhotometricData readPhotometricFile(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".ies" && extension != ".ldt") {
    throw PhotometricError(file, 0, "",
                           "unknown photometric format: expected a .ies (IES LM-63) or .ldt "
                           "(EULUMDAT) file");
  }
  const std::string text = readPhotometricText(file);
  return extension == ".ies" ? parseIes(text, file) : parseLdt(text, file);
}

}  // namespace penumbra::photometry
