#pragma once
// The .csv, .res and .pts files of one grid (grid_rows.hpp), written batch by batch while the grid
// is evaluated (streamGrid), so that no per-point data outlives its batch; the bytes are those
// writeGridCsv, writeGridRes and writeGridPts write for the same values.
//
// write() copies the batch's values and returns: a thread of the writer's own turns them into
// text and writes them while the next batch is classified and computed. At most two batches are
// held (the one being written and the one waiting), so memory does not grow with the grid.
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "grid/grid_evaluation.hpp"
#include "output/grid_rows.hpp"
#include "scene/scene.hpp"

namespace penumbra {

class GridFileWriter {
 public:
  // Creates <directory>/<stem>.csv, .res and .pts (gridFileStem) and writes the CSV header. `grid`
  // must outlive the writer.
  // With `withParts`, the CSV has the direct and indirect columns (grid_rows.hpp); E is written
  // with `digits` (illuminanceDigits).
  GridFileWriter(const std::filesystem::path& directory, const Scene& scene,
                 const CalculationGrid& grid, bool withParts, NumberDigits digits);
  // Without close(): stops after the batch being written; the files stay as they are.
  ~GridFileWriter();
  GridFileWriter(const GridFileWriter&) = delete;
  GridFileWriter& operator=(const GridFileWriter&) = delete;

  // Hands on the batch; waits while an earlier one still waits. Throws std::runtime_error naming
  // a file that an earlier batch failed to write.
  void write(const GridBatch& batch);
  // Writes what is left, flushes and closes the files; throws std::runtime_error naming a file
  // that failed.
  void close();

 private:
  struct Batch {
    std::size_t first = 0;
    std::vector<double> illuminance;
    std::vector<double>
        direct;               // empty: direct = illuminance (a direct-only run, or inside points)
    std::vector<double> sun;  // empty: no sun
    std::vector<double> sunReflected;  // empty: no sun, a direct-only run or inside points
    // lx, the sky and externally reflected components; empty: not split (a direct-only run,
    // no sky, or inside points)
    std::vector<double> skyComponent, externalComponent;
    std::vector<int> inside;
  };
  void writeBatches();              // the thread
  void writeBatch(const Batch& b);  // text and bytes, on the thread

  const CalculationGrid* grid_;
  bool withParts_ = false;
  std::vector<std::string> insideNames_;  // per solid, as a CSV field
  std::filesystem::path csvPath_, resPath_, ptsPath_;
  std::ofstream csv_, res_, pts_;
  GridRows rows_;

  std::mutex mutex_;
  std::condition_variable changed_;
  std::optional<Batch> waiting_;  // handed on, not yet taken by the thread
  Batch spare_;                   // the last written batch's vectors, reused
  bool stopping_ = false;         // no more batches come
  bool abandoned_ = false;        // destroyed without close(): skip what still waits
  std::exception_ptr error_;      // the first failure on the thread
  std::thread thread_;
};

}  // namespace penumbra
