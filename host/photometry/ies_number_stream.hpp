#pragma once
// The numeric part of an IES file (after the TILT line): numbers separated by white space or
// commas, split across lines anyhow (LM-63 allows any line breaks). Each read names its field,
// so that a missing or non-numeric value is reported at its line with what was expected.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "photometry/field_checks.hpp"

namespace penumbra::photometry {

class IesNumberStream {
 public:
  // `text` starts at line `firstLine` (1-based) of `file`; `lastLine` is the file's last line,
  // where a value missing at the end is reported.
  IesNumberStream(std::string_view text, int firstLine, int lastLine, std::filesystem::path file);

  // The next number; PhotometricError when the file ends or the word is not a number.
  double number(const std::string& field);
  // The next number, which must be a whole number in [min, max] ("37" or "37.0").
  int integer(const std::string& field, int min, int max, const std::string& meaning = "");
  // `count` numbers; at the end of the file: "expected N values, found K (the file ends)".
  NumberedValues values(const std::string& field, std::size_t count);

  int line() const { return tokenLine_; }  // the line of the word read last
  // Words left after the table (numbers or not), and the line of the first.
  std::size_t wordsLeft(int& firstLine);
  const std::filesystem::path& file() const { return file_; }

 private:
  // The next word, or an empty view at the end of the text.
  std::string_view nextWord();

  std::string_view text_;
  std::size_t pos_ = 0;
  int line_;
  int tokenLine_;
  int lastLine_;
  std::filesystem::path file_;
};

}  // namespace penumbra::photometry
