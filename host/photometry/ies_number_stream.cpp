#include "photometry/ies_number_stream.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "photometry/photometric_error.hpp"
#include "photometry/photometric_text.hpp"

namespace penumbra::photometry {

IesNumberStream::IesNumberStream(std::string_view text, int firstLine, int lastLine,
                                 std::filesystem::path file)
    : text_(text),
      line_(firstLine),
      tokenLine_(firstLine),
      lastLine_(lastLine),
      file_(std::move(file)) {}

std::string_view IesNumberStream::nextWord() {
  // Ctrl-Z ends old DOS files.
  const auto separator = [](char c) {
    return c == ' ' || c == '\t' || c == ',' || c == '\n' || c == '\r' || c == '\v' || c == '\f' ||
           c == '\x1a';
  };
  while (pos_ < text_.size() && separator(text_[pos_])) {
    const char c = text_[pos_];
    // A line ends at LF, CRLF or a lone CR.
    if (c == '\n' || (c == '\r' && (pos_ + 1 >= text_.size() || text_[pos_ + 1] != '\n'))) {
      ++line_;
    }
    ++pos_;
  }
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !separator(text_[pos_])) ++pos_;
  tokenLine_ = line_;
  return text_.substr(start, pos_ - start);
}

double IesNumberStream::number(const std::string& field) {
  const std::string_view word = nextWord();
  if (word.empty()) throw PhotometricError(file_, lastLine_, field, "missing (the file ends)");
  const auto value = parseNumber(word);
  if (!value) {
    throw PhotometricError(file_, tokenLine_, field,
                           "expected a number, found " + quoteForMessage(word));
  }
  return *value;
}

int IesNumberStream::integer(const std::string& field, int min, int max,
                             const std::string& meaning) {
  const double value = number(field);
  return wholeNumber(value, min, max, meaning, file_, tokenLine_, field);
}

NumberedValues IesNumberStream::values(const std::string& field, std::size_t count) {
  NumberedValues out;
  out.values.reserve(std::min<std::size_t>(count, 4096));
  out.lines.reserve(std::min<std::size_t>(count, 4096));
  for (std::size_t i = 0; i < count; ++i) {
    const std::string_view word = nextWord();
    if (word.empty()) {
      throw PhotometricError(file_, lastLine_, field,
                             fmt::format("expected {} values, found {} (the file ends)", count, i));
    }
    const auto value = parseNumber(word);
    if (!value) {
      throw PhotometricError(file_, tokenLine_, field,
                             fmt::format("value {} of {}: expected a number, found {}", i + 1,
                                         count, quoteForMessage(word)));
    }
    out.values.push_back(*value);
    out.lines.push_back(tokenLine_);
  }
  return out;
}

std::size_t IesNumberStream::wordsLeft(int& firstLine) {
  std::size_t count = 0;
  while (!nextWord().empty()) {
    if (count++ == 0) firstLine = tokenLine_;
  }
  return count;
}

}  // namespace penumbra::photometry
