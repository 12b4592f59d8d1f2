#include "photometry/photometric_error.hpp"

#include <fmt/format.h>

namespace penumbra::photometry {
namespace {

// The form compilers use ("file:line: field: message"), which editors turn into a link.
std::string describe(const std::filesystem::path& file, int line, const std::string& field,
                     const std::string& message) {
  std::string text = file.string();
  if (line > 0) text += fmt::format(":{}", line);
  text += ": ";
  if (!field.empty()) text += field + ": ";
  return text + message;
}

}  // namespace

PhotometricError::PhotometricError(std::filesystem::path file, int line, std::string field,
                                   const std::string& message)
    : std::runtime_error(describe(file, line, field, message)),
      file_(std::move(file)),
      line_(line),
      field_(std::move(field)),
      message_(message) {}

}  // namespace penumbra::photometry
