// The degenerate-geometry stress suite (docs/reliability.md): N seeded configurations
// (bench/degenerate_scenes.hpp) through the kernel, checked against the unoccluded E and the
// independent reference (bench/degenerate_check.hpp). Prints the figures and every failure;
// exit status 1 when a point fails.
//   usage: degenerate_stress [--configurations N] [--seed S] [--first I] [--reference-n n]
//                            [--thin METRES] [--device cpu|gpu|<index>]
// --thin sets the thickness of the "thin" boxes (default 1 cm, what the suite holds to).
#include <fmt/format.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include "bench/degenerate_check.hpp"
#include "cl/device.hpp"

int main(int argc, char** argv) {
  using namespace penumbra;
  long configurations = 10000, first = 0;
  std::uint64_t seed = 1;
  int referenceN = bench::kStressReferenceN;
  std::string device = "cpu";
  double thin = bench::DegenerateGenerator::kThinBox;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--configurations")
      configurations = std::atol(argv[i + 1]);
    else if (flag == "--seed")
      seed = std::strtoull(argv[i + 1], nullptr, 10);
    else if (flag == "--first")
      first = std::atol(argv[i + 1]);
    else if (flag == "--reference-n")
      referenceN = std::atoi(argv[i + 1]);
    else if (flag == "--device")
      device = argv[i + 1];
    else if (flag == "--thin")
      thin = std::atof(argv[i + 1]);
    else {
      fmt::print(stderr, "degenerate_stress: unknown option {}\n", flag);
      return 2;
    }
  }
  compute::Device clDevice = compute::Device::select(device);
  bench::DegenerateCase first_case = bench::DegenerateGenerator::make(seed, first, thin);
  IlluminanceEngine engine(clDevice, first_case.scene), open(clDevice, first_case.scene);
  bench::StressFigures figures;
  for (long i = first; i < first + configurations; ++i) {
    bench::checkDegenerateCase(bench::DegenerateGenerator::make(seed, i, thin), engine, open,
                               referenceN, figures);
    if ((i - first + 1) % 500 == 0) {
      fmt::print(
          stderr, "degenerate_stress: {} / {} configurations, {} points, {} failed, worst {:.3e}\n",
          i - first + 1, configurations, figures.points, figures.failed(), figures.worstRelative);
    }
  }
  for (const std::string& f : figures.failures) fmt::print("FAIL {}\n", f);
  fmt::print(
      "configurations {} (seed {}, first {}, thin boxes {} m), points {} (and {} inside solids, "
      "skipped), reference n {}\n"
      "non-finite {}, negative {}, above unoccluded {}, off the reference {}\n"
      "worst |E - E_ref| / E_unoccluded {:.3e} at {}\n",
      figures.configurations, seed, first, thin, figures.points, figures.insideSolids, referenceN,
      figures.nonFinite, figures.negative, figures.aboveUnoccluded, figures.beyondReference,
      figures.worstRelative, figures.worstCase);
  return figures.failed() == 0 ? 0 : 1;
}
