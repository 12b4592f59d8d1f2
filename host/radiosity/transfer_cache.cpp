#include "radiosity/transfer_cache.hpp"

#include "geometry/fnv1a_hash.hpp"

namespace penumbra {

std::uint64_t transferFingerprint(const Scene& scene, const SurfaceMesh& mesh) {
  Fnv1a h;
  h.add(std::string_view("penumbra transfer 1"));
  for (const Solid& solid : scene.solids) {
    h.add(std::string_view("solid"));
    for (std::size_t f = 0; f < solid.shape.faces().size(); ++f)
      h.add(solid.shape.facePolygon(static_cast<int>(f)));
  }
  if (scene.room) {
    h.add(scene.room->size);
    h.add(scene.room->wallThickness);
    for (const Opening& opening : scene.room->openings) {
      h.add(opening.inner);
      h.add(opening.outer);
    }
  }
  for (const SurfaceElement& element : mesh.elements) {
    h.add(element.polygon);
    h.add(static_cast<double>(element.solid));
    h.add(static_cast<double>(element.face));
  }
  for (std::size_t node = 0; node < mesh.nodes.size(); ++node) {
    h.add(mesh.nodes[node].position);
    h.add(mesh.nodes[node].normal);
    h.add(mesh.weights[node]);
  }
  return h.value();
}

std::shared_ptr<GeometryTransfer> TransferCache::find(std::uint64_t key) {
  for (auto it = entries_.begin(); it != entries_.end(); ++it) {
    if (it->key != key) continue;
    entries_.splice(entries_.begin(), entries_, it);  // most recently used first
    return entries_.front().transfer;
  }
  return nullptr;
}

void TransferCache::insert(std::uint64_t key, std::shared_ptr<GeometryTransfer> transfer) {
  entries_.push_front({key, std::move(transfer)});
  std::size_t bytes = 0;
  for (auto it = entries_.begin(); it != entries_.end(); ++it) {
    bytes += it->transfer->bytes();
    if (it != entries_.begin() && bytes > budget_) {
      entries_.erase(it, entries_.end());
      break;
    }
  }
}

}  // namespace penumbra
