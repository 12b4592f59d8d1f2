#pragma once
// Work that may abort the whole process (VTK calls abort() when its X display goes away) run in a
// forked child, so that the parent survives it, keeps what it computed and says what is missing.
#include <functional>

namespace penumbra {

// Runs `work` in a child process (fork) and waits for it. Returns when `work` returned. Throws
// std::runtime_error with the child's error message when `work` threw, and with the signal
// ("killed by signal 6 (Aborted)") when the child died. The child shares nothing back but the
// files it wrote; it must not use the parent's threads (OpenCL queues, TBB), only its own.
void runInChildProcess(const std::function<void()>& work);

}  // namespace penumbra
