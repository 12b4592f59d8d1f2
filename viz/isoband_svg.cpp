#include "viz/isoband_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <stdexcept>

#include "geometry/face_outside_solids.hpp"
#include "geometry/tolerance.hpp"
#include "output/image_files.hpp"
#include "output/render_files.hpp"
#include "render/camera.hpp"
#include "viz/colour_scale.hpp"
#include "viz/nice_numbers.hpp"

namespace penumbra::viz {
namespace {

std::string hex(const Rgb& c) {
  const auto byte = [](double v) {
    return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
  };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(c[0]), byte(c[1]), byte(c[2]));
}

std::string bandColour(int band, int bandCount) {
  return hex(bandRgb(band, bandCount));
}

struct Point2 {
  double x, y;
};

std::string pointsAttribute(const std::vector<Point2>& points) {
  std::string out;
  for (const Point2& p : points) out += fmt::format("{:.2f},{:.2f} ", p.x, p.y);
  if (!out.empty()) out.pop_back();
  return out;
}

// The legend: one swatch per band with its range in lx, at (x, y), drawn downwards.
std::string legendSvg(const std::vector<double>& levels, double x, double y) {
  const int bands = static_cast<int>(levels.size()) + 1;
  const double step = levels.size() >= 2 ? levels[1] - levels[0] : (levels.empty() ? 1 : levels[0]);
  std::string out = fmt::format(
      "<g font-family=\"DejaVu Sans, sans-serif\" font-size=\"13\">\n"
      "<text x=\"{:.1f}\" y=\"{:.1f}\" font-weight=\"bold\">E [lx]</text>\n",
      x, y);
  for (int b = bands - 1; b >= 0; --b) {
    const double top = y + 10 + (bands - 1 - b) * 20;
    const std::string label =
        b == 0 ? fmt::format("&lt; {}", formatTick(levels.front(), step))
        : b == bands - 1
            ? fmt::format("≥ {}", formatTick(levels.back(), step))
            : fmt::format("{} – {}", formatTick(levels[b - 1], step), formatTick(levels[b], step));
    out += fmt::format(
        "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"24\" height=\"18\" fill=\"{}\" stroke=\"#333\" "
        "stroke-width=\"0.5\"/><text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n",
        x, top, bandColour(b, bands), x + 30, top + 14, label);
  }
  return out + "</g>\n";
}

void writeSvg(const std::filesystem::path& path, const std::string& body, double width,
              double height) {
  // Written under a temporary name and renamed: never a half-written drawing.
  const std::filesystem::path temporary = path.string() + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) throw std::runtime_error("cannot create " + temporary.string());
    out << fmt::format(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
        "width=\"{0:.0f}\" height=\"{1:.0f}\" viewBox=\"0 0 {0:.0f} {1:.0f}\">\n"
        "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n",
        width, height);
    out << body << "</svg>\n";
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::filesystem::rename(temporary, path);
}

// The polygons of one surface's bands and its contour lines, projected by `project`. The
// surface's most common band is drawn once, as the whole `outline`, and the others on top: the
// file is smaller, and no hairline seams show between the small polygons of large areas.
template <typename Project>
std::string surfaceSvg(const IsoBands& bands, const std::vector<Vec3>& outline, int bandCount,
                       const Project& project) {
  std::vector<int> count(bandCount, 0);
  for (const IsoBandPolygon& polygon : bands.polygons) ++count[polygon.band];
  const int common = static_cast<int>(std::max_element(count.begin(), count.end()) - count.begin());
  std::string out = "<g>\n";
  {
    std::vector<Point2> points;
    for (const Vec3& v : outline) points.push_back(project(v));
    const std::string colour = bandColour(common, bandCount);
    out += fmt::format("<polygon points=\"{}\" fill=\"{}\" stroke=\"{}\" stroke-width=\"0.6\"/>\n",
                       pointsAttribute(points), colour, colour);
  }
  // Every other band as one path: its polygons' edges that no other polygon of the band shares
  // (the band's outline, holes included), chained into loops and filled even-odd. So the size
  // of the drawing follows the bands and their outlines, not the mesh.
  using Key = std::array<double, 3>;
  const auto key = [](const Vec3& v) { return Key{v.x(), v.y(), v.z()}; };
  for (int band = 0; band < bandCount; ++band) {
    if (band == common || count[band] == 0) continue;
    std::map<std::pair<Key, Key>, int> edges;  // directed edge → times seen
    std::map<Key, Vec3> at;
    for (const IsoBandPolygon& polygon : bands.polygons) {
      if (polygon.band != band) continue;
      const auto& v = polygon.vertices;
      for (std::size_t i = 0; i < v.size(); ++i) {
        const Key a = key(v[i]), b = key(v[(i + 1) % v.size()]);
        if (a == b) continue;
        at[a] = v[i];
        // An edge two polygons share runs both ways: both go.
        if (const auto back = edges.find({b, a}); back != edges.end()) {
          if (--back->second == 0) edges.erase(back);
        } else {
          ++edges[{a, b}];
        }
      }
    }
    std::multimap<Key, Key> next;
    for (const auto& [edge, times] : edges)
      for (int t = 0; t < times; ++t) next.emplace(edge.first, edge.second);
    std::string path;
    while (!next.empty()) {
      auto it = next.begin();
      const Key start = it->first;
      Key current = start;
      const Point2 p0 = project(at[start]);
      path += fmt::format("M{:.2f},{:.2f}", p0.x, p0.y);
      while (it != next.end()) {
        current = it->second;
        next.erase(it);
        if (current == start) break;
        const Point2 p = project(at[current]);
        path += fmt::format("L{:.2f},{:.2f}", p.x, p.y);
        it = next.find(current);
      }
      path += "Z";
    }
    const std::string colour = bandColour(band, bandCount);
    // The stroke in the fill's colour closes the hairline gaps renderers leave between shapes.
    out += fmt::format(
        "<path d=\"{}\" fill=\"{}\" fill-rule=\"evenodd\" stroke=\"{}\" stroke-width=\"0.6\"/>\n",
        path, colour, colour);
  }
  // The isolux lines: their pieces (one per triangle) chained end to end into one path.
  std::multimap<Key, std::size_t> ends;
  const auto& segments = bands.contourSegments;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    ends.emplace(key(segments[s][0]), s);
    ends.emplace(key(segments[s][1]), s);
  }
  std::vector<bool> used(segments.size(), false);
  const auto take = [&](const Vec3& from, std::size_t& s) {  // an unused piece ending at `from`
    const auto [lo, hi] = ends.equal_range(key(from));
    for (auto it = lo; it != hi; ++it)
      if (!used[it->second]) {
        s = it->second;
        return true;
      }
    return false;
  };
  std::string lines;
  for (std::size_t first = 0; first < segments.size(); ++first) {
    if (used[first]) continue;
    used[first] = true;
    // Walk back to one end of the chain, then draw it forwards.
    std::vector<Vec3> chain{segments[first][0], segments[first][1]};
    for (std::size_t s; take(chain.back(), s);) {
      used[s] = true;
      chain.push_back(key(segments[s][0]) == key(chain.back()) ? segments[s][1] : segments[s][0]);
    }
    for (std::size_t s; take(chain.front(), s);) {
      used[s] = true;
      chain.insert(chain.begin(),
                   key(segments[s][0]) == key(chain.front()) ? segments[s][1] : segments[s][0]);
    }
    for (std::size_t i = 0; i < chain.size(); ++i) {
      const Point2 p = project(chain[i]);
      lines += fmt::format("{}{:.2f},{:.2f}", i == 0 ? "M" : "L", p.x, p.y);
    }
  }
  if (!lines.empty()) {
    out += fmt::format(
        "<path d=\"{}\" fill=\"none\" stroke=\"#1e1e1e\" stroke-width=\"0.7\" "
        "stroke-opacity=\"0.7\"/>\n",
        lines);
  }
  return out + "</g>\n";
}

// The painter's order of convex planar pieces that face the eye and do not intersect (Newell,
// Newell & Sancha, simplified): when their pictures overlap, a piece is drawn before another if it
// lies wholly behind the other's plane, or the other wholly in front of its own (as seen from the
// eye). A topological order of those constraints, the
// farthest (by centroid depth) first among the free ones; a cycle (which non-intersecting convex
// pieces rarely form) is broken at the farthest piece.
template <typename Outline, typename Depth, typename Project>
std::vector<std::size_t> paintersOrder(std::size_t n, const Outline& outline, const Depth& depth,
                                       const Camera& camera, const Project& project,
                                       double tolerance) {
  struct Box {
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  };
  std::vector<Box> boxes(n);
  std::vector<Plane> planes(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (const Vec3& v : outline(i)) {
      const Point2 p = project(v);
      boxes[i] = {std::min(boxes[i].x0, p.x), std::min(boxes[i].y0, p.y),
                  std::max(boxes[i].x1, p.x), std::max(boxes[i].y1, p.y)};
    }
    Plane plane = ConvexPolygon(outline(i)).plane();
    if (plane.signedDistance(camera.eye) < 0.0) plane = plane.flipped();  // towards the eye
    planes[i] = plane;
  }
  const auto behind = [&](std::size_t i, std::size_t j) {  // i wholly behind j's plane
    for (const Vec3& v : outline(i))
      if (planes[j].signedDistance(v) > tolerance) return false;
    return true;
  };
  const auto inFront = [&](std::size_t i, std::size_t j) {  // i wholly on the eye's side of j's
    for (const Vec3& v : outline(i))
      if (planes[j].signedDistance(v) < -tolerance) return false;
    return true;
  };
  // i must be drawn before j.
  const auto before = [&](std::size_t i, std::size_t j) { return behind(i, j) || inFront(j, i); };
  std::vector<std::vector<std::size_t>> after(n);  // i must be drawn before every after[i]
  std::vector<int> blockers(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const Box &a = boxes[i], &b = boxes[j];
      if (a.x1 < b.x0 || b.x1 < a.x0 || a.y1 < b.y0 || b.y1 < a.y0) continue;
      const bool iFirst = before(i, j), jFirst = before(j, i);
      if (iFirst == jFirst) continue;  // coplanar, or no plane separates them
      const std::size_t first = iFirst ? i : j, second = iFirst ? j : i;
      after[first].push_back(second);
      ++blockers[second];
    }
  std::vector<std::size_t> order;
  std::vector<bool> done(n, false);
  while (order.size() < n) {
    std::size_t pick = n;
    for (std::size_t i = 0; i < n; ++i)
      if (!done[i] && blockers[i] == 0 && (pick == n || depth(i) > depth(pick))) pick = i;
    if (pick == n)  // a cycle: the farthest remaining piece goes first
      for (std::size_t i = 0; i < n; ++i)
        if (!done[i] && (pick == n || depth(i) > depth(pick))) pick = i;
    done[pick] = true;
    order.push_back(pick);
    for (std::size_t k : after[pick]) --blockers[k];
  }
  return order;
}

}  // namespace

Rgb bandRgb(int band, int bandCount) {
  return paletteColour(Palette::Viridis, (band + 0.5) / bandCount);
}

std::vector<double> isobandLevels(double eMax, int bands) {
  if (!(eMax > 0.0) || bands < 1) return {1.0};
  // The 1-2-5 series, three levels a decade, the top `bands` - 1 of them below eMax: a room lit
  // by a window spans decades, and equal steps would put most of it in the lowest band.
  std::vector<double> levels = oneTwoFiveBetween(0.0, eMax);
  if (levels.empty()) levels.push_back(oneTwoFiveAtMost(eMax));
  if (static_cast<int>(levels.size()) > bands - 1)
    levels.erase(levels.begin(), levels.end() - std::max(bands - 1, 1));
  return levels;
}

std::vector<FaceBands> viewFaceBands(const Scene& scene, const View& view, const PointLight& light,
                                     std::vector<double>& levels, int bands, double spacing) {
  if (spacing <= 0.0) spacing = std::max(scene.size(), 1.0) / 50.0;
  const double tolerance = Tolerance::kRelativeInput * std::max(scene.size(), 1.0);
  std::vector<FaceBands> faces;
  for (int s = 0; s < static_cast<int>(scene.solids.size()); ++s) {
    const ConvexPolyhedron& shape = scene.solids[s].shape;
    for (int f = 0; f < static_cast<int>(shape.faces().size()); ++f) {
      const Plane& plane = shape.faces()[f].plane;
      // Faces turned away from the eye are hidden by their own solid: not drawn.
      if (plane.signedDistance(view.eye) <= 0.0) continue;
      // Only what no other solid covers (the floor under a wall is not drawn, and its E of 0
      // would show through wherever the painter's order is unsure).
      std::vector<const ConvexPolyhedron*> others;
      for (int o = 0; o < static_cast<int>(scene.solids.size()); ++o)
        if (o != s) others.push_back(&scene.solids[o].shape);
      for (ConvexPolygon& piece : faceOutsideSolids(shape.facePolygon(f), others, tolerance)) {
        FaceBands face;
        face.solid = s;
        face.face = f;
        face.polygon = std::move(piece);
        face.mesh = triangulate(face.polygon, spacing);
        faces.push_back(std::move(face));
      }
    }
  }
  // E at every mesh vertex of every face, in one batch.
  std::vector<SamplePoint> points;
  for (const FaceBands& face : faces)
    for (const Vec3& v : face.mesh.vertices)
      points.push_back(SamplePoint{
          v, scene.solids[face.solid].shape.faces()[face.face].plane.normal, face.solid});
  const std::vector<double> e = light(points);
  std::size_t next = 0;
  double eMax = 0.0;
  for (FaceBands& face : faces) {
    face.illuminance.assign(e.begin() + next, e.begin() + next + face.mesh.vertices.size());
    next += face.mesh.vertices.size();
    for (double v : face.illuminance) eMax = std::max(eMax, v);
  }
  levels = isobandLevels(eMax, bands);
  for (FaceBands& face : faces) {
    const Vec3 normal = scene.solids[face.solid].shape.faces()[face.face].plane.normal;
    const int solid = face.solid;
    face.bands = isoBands(face.mesh, face.illuminance, levels, [&](std::span<const Vec3> at) {
      std::vector<SamplePoint> probes;
      for (const Vec3& p : at) probes.push_back(SamplePoint{p, normal, solid});
      return light(probes);
    });
  }
  return faces;
}

IsobandFigure writeViewIsobands(const Scene& scene, const View& view, const PointLight& light,
                                int bands, const std::filesystem::path& svg, double spacing) {
  IsobandFigure figure;
  std::vector<FaceBands> faces = viewFaceBands(scene, view, light, figure.levels, bands, spacing);
  const Camera camera = Camera::forView(view, 1);
  const double nearDepth = 1e-3 * std::max(scene.size(), 1.0);
  // The part of a polygon in front of the eye, projected to pixels.
  const Plane nearPlane{-camera.forward, -(camera.forward.dot(camera.eye) + nearDepth)};
  const auto visiblePart = [&](const std::vector<Vec3>& polygon) {
    return ConvexPolygon(polygon).clipped(nearPlane, 0.0);
  };
  const auto project = [&](const Vec3& p) {
    const Eigen::Vector2d s = *camera.project(p, 0.0);
    return Point2{s.x(), s.y()};
  };
  // Painter's algorithm: farthest face first, by the depth of its centroid.
  struct Drawn {
    double depth;
    std::string svg;
    std::vector<Vec3> outline;  // the piece in front of the eye, for the drawing order
  };
  std::vector<Drawn> drawn;
  const int bandCount = static_cast<int>(figure.levels.size()) + 1;
  for (const FaceBands& face : faces) {
    IsoBands clipped;
    for (const IsoBandPolygon& polygon : face.bands.polygons) {
      const ConvexPolygon part = visiblePart(polygon.vertices);
      if (!part.empty()) clipped.polygons.push_back({polygon.band, part.vertices()});
    }
    for (const auto& segment : face.bands.contourSegments)
      if (camera.depth(segment[0]) > nearDepth && camera.depth(segment[1]) > nearDepth)
        clipped.contourSegments.push_back(segment);
    if (clipped.polygons.empty()) continue;
    figure.polygons += clipped.polygons.size();
    figure.contourSegments += clipped.contourSegments.size();
    ++figure.faces;
    const ConvexPolygon outline = visiblePart(face.polygon.vertices());
    if (outline.empty()) continue;
    drawn.push_back({camera.depth(face.polygon.centroid()),
                     surfaceSvg(clipped, outline.vertices(), bandCount, project),
                     outline.vertices()});
  }
  // Sources facing the eye, white with a warm edge, in the same order.
  for (const Source& source : scene.sources)
    for (const ConvexPolygon& face : source.faces) {
      if (face.plane().signedDistance(view.eye) <= 0.0) continue;
      const ConvexPolygon part = visiblePart(face.vertices());
      if (part.empty()) continue;
      std::vector<Point2> points;
      for (const Vec3& v : part.vertices()) points.push_back(project(v));
      drawn.push_back({camera.depth(face.centroid()),
                       fmt::format("<polygon points=\"{}\" fill=\"#ffffff\" stroke=\"{}\" "
                                   "stroke-width=\"1\"/>\n",
                                   pointsAttribute(points), hex(kSourceEdge)),
                       part.vertices()});
    }
  const std::vector<std::size_t> order = paintersOrder(
      drawn.size(), [&](std::size_t i) -> const std::vector<Vec3>& { return drawn[i].outline; },
      [&](std::size_t i) { return drawn[i].depth; }, camera, project,
      Tolerance::kRelativeInput* std::max(scene.size(), 1.0));
  std::string body = fmt::format(
      "<svg x=\"0\" y=\"0\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 0 {0} {1}\" overflow=\"hidden\">\n",
      view.width, view.height);
  for (std::size_t i : order) body += drawn[i].svg;
  body += "</svg>\n";
  body += legendSvg(figure.levels, view.width + 16, 24);
  writeSvg(svg, body, view.width + 150, std::max(view.height, 60 + 20 * bandCount));
  return figure;
}

DisplayImage bandedRaster(const RenderedView& rendered, const Scene& scene,
                          std::span<const double> levels) {
  std::size_t solidFaces = 0;  // face ids above this are sources (render/visible_scene.hpp)
  for (const Solid& s : scene.solids) solidFaces += s.shape.faces().size();
  const int w = rendered.view.width, h = rendered.view.height;
  const int bandCount = static_cast<int>(levels.size()) + 1;
  DisplayImage image{w, h, 3, std::vector<uint8_t>(static_cast<std::size_t>(w) * h * 3, 0)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint32_t id = rendered.faces.at(x, y);
      Rgb colour{0.0, 0.0, 0.0};
      if (id > solidFaces) colour = kWhite;
      if (id != 0 && id <= solidFaces)
        colour = bandRgb(bandOf(rendered.illuminance.at(x, y), levels), bandCount);
      for (int c = 0; c < 3; ++c)
        image.values[(static_cast<std::size_t>(y) * w + x) * 3 + c] =
            static_cast<uint8_t>(std::lround(255.0 * colour[c]));
    }
  return image;
}

IsobandFigure writeViewIsobandFiles(const Scene& scene, const RenderedView& rendered,
                                    const PointLight& light, int bands,
                                    const std::filesystem::path& folder) {
  const std::string stem = viewFileStem(rendered.view.name);
  const IsobandFigure figure =
      writeViewIsobands(scene, rendered.view, light, bands, folder / (stem + ".svg"));
  writePng(folder / (stem + ".isobands.png"), bandedRaster(rendered, scene, figure.levels),
           {{"penumbra:view", rendered.view.name}, {"penumbra:units", "band colours of E (lx)"}});
  return figure;
}

IsobandFigure writeGridIsobands(const CalculationGrid& grid, std::span<const double> illuminance,
                                const PointLight& light, int bands,
                                const std::filesystem::path& svg, int widthPx) {
  if (grid.kind == GridKind::Points || grid.columns < 2 || grid.rows < 2) {
    throw std::invalid_argument("iso-bands need a planar grid of at least 2 × 2 points");
  }
  IsobandFigure figure;
  TriangleMesh mesh;
  mesh.vertices.reserve(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) mesh.vertices.push_back(grid.position(i));
  const auto at = [&](int c, int r) { return r * grid.columns + c; };
  for (int r = 0; r + 1 < grid.rows; ++r)
    for (int c = 0; c + 1 < grid.columns; ++c) {
      mesh.triangles.push_back({at(c, r), at(c + 1, r), at(c + 1, r + 1)});
      mesh.triangles.push_back({at(c, r), at(c + 1, r + 1), at(c, r + 1)});
    }
  const double eMax = *std::max_element(illuminance.begin(), illuminance.end());
  figure.levels = isobandLevels(eMax, bands);
  const Vec3 normal = grid.normal(0);
  const IsoBands result =
      isoBands(mesh, illuminance, figure.levels, [&](std::span<const Vec3> points) {
        std::vector<SamplePoint> probes;
        for (const Vec3& p : points) probes.push_back(SamplePoint{p, normal, -1});
        return light(probes);
      });
  figure.polygons = result.polygons.size();
  figure.contourSegments = result.contourSegments.size();
  figure.faces = 1;
  // Plan coordinates: u along the rows, v along the columns, v upwards on the page.
  const Vec3 origin = grid.position(at(0, 0));
  const Vec3 u = grid.position(at(grid.columns - 1, 0)) - origin;
  const Vec3 v = grid.position(at(0, grid.rows - 1)) - origin;
  const double margin = 20.0, scale = (widthPx - 2 * margin) / u.norm();
  const double height = v.norm() * scale + 2 * margin;
  const auto project = [&](const Vec3& p) {
    const Vec3 d = p - origin;
    return Point2{margin + d.dot(u.normalized()) * scale,
                  height - margin - d.dot(v.normalized()) * scale};
  };
  const int bandCount = static_cast<int>(figure.levels.size()) + 1;
  const std::vector<Vec3> outline{origin, origin + u, origin + u + v, origin + v};
  std::string body = surfaceSvg(result, outline, bandCount, project);
  body += legendSvg(figure.levels, widthPx + 16, 24);
  writeSvg(svg, body, widthPx + 150, std::max(height, 60.0 + 20 * bandCount));
  return figure;
}

}  // namespace penumbra::viz
