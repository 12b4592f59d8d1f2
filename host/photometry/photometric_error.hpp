#pragma once
#include <filesystem>
#include <stdexcept>
#include <string>

namespace penumbra::photometry {

// A malformed photometric file (IES LM-63 or EULUMDAT): names the file, the line (1-based, 0 for
// the file as a whole; the last line when the file ends early) and the field ("number of vertical
// angles", "candela values"), with a message a person can act on. Its text reads "downlight.ies:14:
// vertical angles: expected 37 values, found 12 (the file ends)".
class PhotometricError : public std::runtime_error {
 public:
  PhotometricError(std::filesystem::path file, int line, std::string field,
                   const std::string& message);
  const std::filesystem::path& file() const { return file_; }
  int line() const { return line_; }
  const std::string& field() const { return field_; }
  const std::string& message() const { return message_; }  // without file, line and field

 private:
  std::filesystem::path file_;
  int line_;
  std::string field_;
  std::string message_;
};

}  // namespace penumbra::photometry
