#pragma once

namespace penumbra {

// `penumbra devices`: prints the OpenCL devices with the index `--device` takes. Exit status 0,
// or 1 when there is none (with what to install).
int runDevicesCommand();

}  // namespace penumbra
