#pragma once
// Runs a program (sbatch, squeue, scancel) and collects what it printed: the only way penumbra
// talks to Slurm, whose commands are its interface (no library, no REST daemon needed).
#include <string>
#include <vector>

namespace penumbra {

struct ProcessResult {
  int status = -1;  // the exit status; 128 + n when killed by signal n
  std::string out, err;
};

// Runs `command` (command[0] looked up in PATH) with no input and waits for it. Throws
// std::runtime_error naming the program when it cannot be started (not installed).
ProcessResult runProcess(const std::vector<std::string>& command);

// `word` quoted for a POSIX shell (single quotes), for the scripts penumbra writes.
std::string shellQuote(const std::string& word);

// Splits `text` into words as a shell would for plain options: blanks separate, single and double
// quotes group ("--comment='a b'" is one word). Throws std::invalid_argument on an unclosed quote.
std::vector<std::string> splitShellWords(const std::string& text);

}  // namespace penumbra
