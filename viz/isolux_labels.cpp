#include "viz/isolux_labels.hpp"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>

namespace penumbra::viz {

namespace {

// Along a polyline: the point at `fraction` of its length.
Eigen::Vector2d pointAlong(const std::vector<Eigen::Vector2d>& line,
                           const std::vector<double>& distance, double fraction) {
  const double target = fraction * distance.back();
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (distance[i] >= target) {
      const double piece = distance[i] - distance[i - 1];
      const double w = piece > 0.0 ? (target - distance[i - 1]) / piece : 0.0;
      return line[i - 1] + w * (line[i] - line[i - 1]);
    }
  }
  return line.back();
}

bool farFromAll(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& others,
                double distance) {
  for (const Eigen::Vector2d& o : others) {
    if ((p - o).norm() < distance) return false;
  }
  return true;
}

}  // namespace

std::vector<IsoluxLabel> placeIsoluxLabels(vtkPolyData* lines, const PlotLayout& layout,
                                           const std::vector<Eigen::Vector2d>& avoid) {
  const double f = layout.fontScale;
  const double shortest = 90 * f;        // a line shorter than this carries no label
  const double clearOfMarkers = 60 * f;  // px from a marker's centre
  const double apart = 120 * f;          // px between two labels
  const double inset = 24 * f;           // px from the plot area's edge
  const Eigen::Vector2d lo = layout.pixel({layout.s0, layout.t0});
  const Eigen::Vector2d hi = layout.pixel({layout.s1, layout.t1});

  std::vector<IsoluxLabel> labels;
  std::vector<Eigen::Vector2d> placed;
  vtkDataArray* levels = lines->GetPointData()->GetScalars();
  vtkCellArray* cells = lines->GetLines();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (cells->InitTraversal(); cells->GetNextCell(count, ids);) {
    if (count < 2 || levels == nullptr) continue;
    std::vector<Eigen::Vector2d> line;
    std::vector<double> distance{0.0};
    for (vtkIdType i = 0; i < count; ++i) {
      double p[3];
      lines->GetPoint(ids[i], p);
      line.push_back(layout.pixel({p[0], p[1]}));
      if (i > 0) distance.push_back(distance.back() + (line[i] - line[i - 1]).norm());
    }
    if (distance.back() < shortest) continue;
    for (double fraction : {0.5, 0.3, 0.7, 0.15, 0.85}) {
      const Eigen::Vector2d p = pointAlong(line, distance, fraction);
      const bool inside = p.x() > lo.x() + inset && p.x() < hi.x() - inset &&
                          p.y() > lo.y() + inset && p.y() < hi.y() - inset;
      if (inside && farFromAll(p, avoid, clearOfMarkers) && farFromAll(p, placed, apart)) {
        labels.push_back({p, levels->GetTuple1(ids[0])});
        placed.push_back(p);
        break;
      }
    }
  }
  return labels;
}

}  // namespace penumbra::viz
