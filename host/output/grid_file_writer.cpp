#include "output/grid_file_writer.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "memory/page_prefault.hpp"
#include "output/result_files.hpp"

namespace penumbra {

GridFileWriter::GridFileWriter(const std::filesystem::path& directory, const Scene& scene,
                               const CalculationGrid& grid, bool withParts, NumberDigits digits)
    : grid_(&grid), withParts_(withParts), rows_(digits) {
  for (const Solid& solid : scene.solids) insideNames_.push_back(csvField(solid.name));
  const std::string stem = gridFileStem(grid.name);
  csvPath_ = directory / (stem + ".csv");
  resPath_ = directory / (stem + ".res");
  ptsPath_ = directory / (stem + ".pts");
  csv_.open(csvPath_, std::ios::binary);
  if (!csv_) throw std::runtime_error("cannot create " + csvPath_.string());
  res_.open(resPath_, std::ios::binary);
  if (!res_) throw std::runtime_error("cannot create " + resPath_.string());
  pts_.open(ptsPath_, std::ios::binary);
  if (!pts_) throw std::runtime_error("cannot create " + ptsPath_.string());
  if (scene.sky) rows_.setOutdoorIlluminance(scene.sky->horizontalIlluminance);
  rows_.setSunColumn(scene.sun.has_value());
  const std::string header = gridCsvHeader(withParts, scene.sky.has_value(), scene.sun.has_value());
  csv_.write(header.data(), static_cast<std::streamsize>(header.size()));
  // A batch's rows (about 80 bytes a point in the three files, their buffers grown by doubling)
  // stay in the writer's memory from batch to batch: mapped at once for a batch of up to
  // 65 536 points, the estimator's (memory/page_prefault.hpp).
  const std::size_t rowBytes = std::min<std::size_t>(grid.size(), std::size_t{1} << 16) * 256;
  thread_ = std::thread([this, rowBytes] {
    prefaultHeap(rowBytes);
    writeBatches();
  });
}

GridFileWriter::~GridFileWriter() {
  if (!thread_.joinable()) return;
  {
    const std::lock_guard lock(mutex_);
    stopping_ = abandoned_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void GridFileWriter::write(const GridBatch& batch) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return !waiting_ || error_; });
  if (error_) std::rethrow_exception(error_);
  Batch& next = waiting_.emplace(std::move(spare_));
  next.first = batch.first;
  next.illuminance.assign(batch.illuminance.begin(), batch.illuminance.end());
  next.direct.assign(batch.direct.begin(), batch.direct.end());
  next.sun.assign(batch.sun.begin(), batch.sun.end());
  next.sunReflected.assign(batch.sunReflected.begin(), batch.sunReflected.end());
  next.skyComponent.assign(batch.skyComponent.begin(), batch.skyComponent.end());
  next.externalComponent.assign(batch.externalComponent.begin(), batch.externalComponent.end());
  next.inside.assign(batch.inside.begin(), batch.inside.end());
  lock.unlock();
  changed_.notify_all();
}

void GridFileWriter::close() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
  if (error_) std::rethrow_exception(error_);
  csv_.close();
  if (!csv_) throw std::runtime_error("cannot write " + csvPath_.string());
  res_.close();
  if (!res_) throw std::runtime_error("cannot write " + resPath_.string());
  pts_.close();
  if (!pts_) throw std::runtime_error("cannot write " + ptsPath_.string());
}

void GridFileWriter::writeBatches() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return waiting_ || stopping_; });
    if (!waiting_ || abandoned_) return;
    Batch batch = std::move(*waiting_);
    waiting_.reset();
    const bool failed = error_ != nullptr;
    lock.unlock();
    changed_.notify_all();  // the slot is free for the next batch
    std::exception_ptr error;
    if (!failed) {
      try {
        writeBatch(batch);
      } catch (...) {
        error = std::current_exception();
      }
    }
    lock.lock();
    if (error && !error_) error_ = error;
    spare_ = std::move(batch);
    if (error) changed_.notify_all();  // a write() waiting for the slot learns of it
  }
}

void GridFileWriter::writeBatch(const Batch& batch) {
  rows_.clear();
  rows_.reserve(batch.illuminance.size());
  for (std::size_t k = 0; k < batch.illuminance.size(); ++k) {
    const std::size_t i = batch.first + k;
    const int inside = batch.inside[k];
    const std::string_view insideField =
        inside >= 0 ? std::string_view(insideNames_.at(inside)) : std::string_view();
    const double direct = batch.direct.empty() ? batch.illuminance[k] : batch.direct[k];
    const GridRowValues values{
        batch.illuminance[k],
        withParts_ ? &direct : nullptr,
        batch.sun.empty() ? 0.0 : batch.sun[k],
        batch.sunReflected.empty() ? 0.0 : batch.sunReflected[k],
        batch.skyComponent.empty() ? nullptr : &batch.skyComponent[k],
        batch.externalComponent.empty() ? nullptr : &batch.externalComponent[k]};
    rows_.add(grid_->position(i), grid_->normal(i), values, insideField);
  }
  csv_.write(rows_.csv().data(), static_cast<std::streamsize>(rows_.csv().size()));
  res_.write(rows_.res().data(), static_cast<std::streamsize>(rows_.res().size()));
  if (!csv_) throw std::runtime_error("cannot write " + csvPath_.string());
  if (!res_) throw std::runtime_error("cannot write " + resPath_.string());
  pts_.write(rows_.pts().data(), static_cast<std::streamsize>(rows_.pts().size()));
  if (!pts_) throw std::runtime_error("cannot write " + ptsPath_.string());
}

}  // namespace penumbra
