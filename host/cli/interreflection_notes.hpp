#pragma once
// What a command says on the terminal about its interreflected light, once the mesh is solved and
// before the long part: solids that reflect nothing, and a dense transfer that links replaced.
// `grid` and `render` say the same.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "radiosity/interreflection.hpp"
#include "radiosity/surface_mesh.hpp"

namespace penumbra {

// Light reaches these solids, but without a material they reflect none of it.
inline void warnAboutBlackSolids(const std::optional<InterreflectionReport>& report) {
  if (!report || report->blackSolids.empty()) return;
  const std::vector<std::string>& names = report->blackSolids;
  fmt::print(stderr,
             "penumbra: warning: {} solid{} without a material reflect{} no light (black): {}\n",
             names.size(), names.size() == 1 ? "" : "s", names.size() == 1 ? "s" : "",
             fmt::join(names, ", "));
}

// The dense transfer was asked for, but its mesh was past the dense limit: links took over.
inline void noteLinksPastDenseLimit(const std::optional<InterreflectionReport>& report,
                                    const MeshOptions& mesh) {
  if (!report || report->denseElements == 0) return;
  fmt::print(stderr,
             "penumbra: the mesh has {} elements at --element-size {} m, more than the {} the "
             "dense transfer takes: hierarchical links at --link-error {} instead ({} links)\n",
             report->denseElements, mesh.elementSize, mesh.maxElements, report->linkError,
             report->links);
}

}  // namespace penumbra
