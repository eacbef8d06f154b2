// Producer/consumer queue for PNG frames.
#include "render/png_pipeline.h"

#include "util/atomic_file.h"

namespace plantsim::render {

PngPipeline::PngPipeline(PngSettings settings, std::size_t max_queued,
                         std::function<void(const std::string&, const std::string&)> sink)
    : settings_(settings),
      max_queued_(std::max<std::size_t>(1, max_queued)),
      sink_(std::move(sink)) {
  if (!sink_)
    sink_ = [](const std::string& bytes, const std::string& path) {
      util::write_file_atomically(path, bytes);
    };
  worker_ = std::thread([this] { run(); });
}

PngPipeline::~PngPipeline() {
  try {
    close();
  } catch (...) {  // destructors must not throw; close() explicitly to see errors
  }
}

void PngPipeline::push(Image image, std::string path) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return queue_.size() < max_queued_ || error_; });
  if (error_) std::rethrow_exception(error_);
  queue_.emplace_back(std::move(image), std::move(path));
  changed_.notify_all();
}

void PngPipeline::close() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
    changed_.notify_all();
  }
  if (worker_.joinable()) worker_.join();
  if (error_) std::rethrow_exception(error_);
}

void PngPipeline::run() {
  for (;;) {
    std::pair<Image, std::string> job;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return !queue_.empty() || closing_; });
      if (queue_.empty()) return;
      job = std::move(queue_.front());
      queue_.pop_front();
      changed_.notify_all();
    }
    try {
      sink_(encode_png(job.first, settings_), job.second);
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
      queue_.clear();
      changed_.notify_all();
      return;
    }
  }
}

}  // namespace plantsim::render
