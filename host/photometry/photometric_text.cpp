#include "photometry/photometric_text.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "photometry/photometric_error.hpp"

namespace penumbra::photometry {

std::string readPhotometricText(const std::filesystem::path& file) {
  std::error_code error;
  if (std::filesystem::is_directory(file, error)) {
    throw PhotometricError(file, 0, "", "is a directory, not a photometric file");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw PhotometricError(file, 0, "", "cannot be read");
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxPhotometricFileBytes) {
      throw PhotometricError(file, 0, "",
                             "is larger than 64 MiB; photometric files are under 1 MB");
    }
  }
  return text;
}

std::string_view withoutByteOrderMark(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  return text;
}

std::vector<std::string_view> splitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\n' && text[i] != '\r') continue;
    lines.push_back(text.substr(start, i - start));
    if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
    start = i + 1;
  }
  if (start < text.size()) lines.push_back(text.substr(start));
  return lines;
}

std::string_view trim(std::string_view text) {
  const auto space = [](char c) {
    return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r' || c == '\n';
  };
  while (!text.empty() && space(text.front())) text.remove_prefix(1);
  while (!text.empty() && space(text.back())) text.remove_suffix(1);
  return text;
}

std::optional<double> parseNumber(std::string_view text, bool decimalComma) {
  std::string copy;
  if (decimalComma && text.find(',') != std::string_view::npos) {
    copy.assign(text);
    for (char& c : copy) {
      if (c == ',') c = '.';
    }
    text = copy;
  }
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty() || text.front() == '+') return std::nullopt;
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::string quoteForMessage(std::string_view text) {
  std::string out = "'";
  for (std::size_t i = 0; i < text.size() && i < 40; ++i) {
    const char c = text[i];
    out += (c >= 32 && c < 127) ? c : '?';
  }
  if (text.size() > 40) out += "...";
  return out + "'";
}

}  // namespace penumbra::photometry
