#pragma once
// Text handling shared by the IES and EULUMDAT readers: the file's bytes with a size limit,
// lines whatever the line ends (LF, CRLF, CR), and numbers read whole and finite.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::photometry {

// The largest photometric file read (bytes): a table of 3601 x 1801 values in 10 characters
// each is 65 MB; real files are under 1 MB.
inline constexpr std::size_t kMaxPhotometricFileBytes = std::size_t{64} << 20;

// Reads `file` whole; PhotometricError (line 0) when it cannot be read or is larger than
// kMaxPhotometricFileBytes.
std::string readPhotometricText(const std::filesystem::path& file);

// `text` without a leading UTF-8 byte order mark (some editors write one).
std::string_view withoutByteOrderMark(std::string_view text);

// The lines of `text` without their ends (LF, CRLF or a lone CR).
std::vector<std::string_view> splitLines(std::string_view text);

// `text` without leading and trailing white space.
std::string_view trim(std::string_view text);

// The whole of `text` as a finite number ("12", "-1", "1.5e3", "+0.25"), or nothing: "1.5x",
// "nan", "inf" and "" are not numbers. `decimalComma` also reads "0,75" (EULUMDAT files written
// with a German locale).
std::optional<double> parseNumber(std::string_view text, bool decimalComma = false);

// `text` shortened to at most 40 characters for a message, with printable ASCII only.
std::string quoteForMessage(std::string_view text);

}  // namespace penumbra::photometry
