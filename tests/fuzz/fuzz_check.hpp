#pragma once
// What every fuzz target asserts about a rejected input (docs/reliability.md): it is one
// SceneError (PhotometricError for the photometry readers), whose text starts with the file it is
// about (the input, or a file the input names: a study's base scene, a scene's .pts) and has a line
// and a message, so that a designer is sent to the spot. Anything else that escapes (a
// YAML::Exception, std::out_of_range, ...) is a bug: the target aborts and libFuzzer keeps the
// input.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "scene/scene_loader.hpp"

namespace penumbra::fuzz {

[[noreturn]] inline void reject(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz: %s: %s\n", what, detail.c_str());
  std::abort();
}

// Calls `parse` on one input; accepts success or a well-formed `Error` (SceneError,
// photometry::PhotometricError: each names its file, line and message).
template <typename Error, typename Parse>
void expectValueOrFileError(Parse parse) {
  try {
    parse();
  } catch (const Error& e) {
    const std::string text = e.what();
    if (e.file().empty()) reject("error names no file", text);
    if (text.rfind(e.file().string() + ":", 0) != 0) {
      reject("message does not start with the file", text);
    }
    if (e.line() < 0) reject("negative line", text);
    if (e.message().empty()) reject("empty message", text);
  } catch (const std::exception& e) {
    reject("not the reader's error", e.what());
  } catch (...) {
    reject("not the reader's error", "(unknown exception)");
  }
}

template <typename Parse>
void expectValueOrSceneError(Parse parse) {
  expectValueOrFileError<SceneError>(parse);
}

}  // namespace penumbra::fuzz
