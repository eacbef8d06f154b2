// Writing a sequence of PNG frames while the next ones are drawn: a worker thread encodes
// and writes finished images (bounded queue, so memory stays flat), using the second core
// while the first renders. Errors in the worker are rethrown by close().
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "render/png_io.h"

namespace plantsim::render {

class PngPipeline {
 public:
  /// `sink(png_bytes, path)` receives each encoded image (default: write the file atomically).
  explicit PngPipeline(PngSettings settings, std::size_t max_queued = 2,
                       std::function<void(const std::string&, const std::string&)> sink = {});
  ~PngPipeline();
  PngPipeline(const PngPipeline&) = delete;
  PngPipeline& operator=(const PngPipeline&) = delete;

  void push(Image image, std::string path);
  /// Waits for every queued image; rethrows the first error of the worker.
  void close();

 private:
  void run();
  PngSettings settings_;
  std::size_t max_queued_;
  std::function<void(const std::string&, const std::string&)> sink_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::pair<Image, std::string>> queue_;
  bool closing_ = false;
  std::exception_ptr error_;
  std::thread worker_;
};

}  // namespace plantsim::render
