#include "backends/multi/device_threads.h"

namespace candela {

DeviceThreads::DeviceThreads(size_t devices) : errors_(devices > 0 ? devices : 1) {
  for (size_t i = 1; i < devices; ++i) workers_.emplace_back([this, i] { serve(i); });
}

DeviceThreads::~DeviceThreads() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void DeviceThreads::run(const std::function<void(size_t)>& task) {
  {
    std::lock_guard lock(mutex_);
    task_ = &task;
    running_ = workers_.size();
    ++round_;
    for (std::exception_ptr& e : errors_) e = nullptr;
  }
  wake_.notify_all();
  try {
    task(0);
  } catch (...) {
    errors_[0] = std::current_exception();
  }
  std::unique_lock lock(mutex_);
  finished_.wait(lock, [this] { return running_ == 0; });
  task_ = nullptr;
  for (const std::exception_ptr& e : errors_)
    if (e) std::rethrow_exception(e);
}

void DeviceThreads::serve(size_t device) {
  uint64_t done = 0;
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stopping_ || round_ != done; });
    if (stopping_) return;
    done = round_;
    const std::function<void(size_t)>& task = *task_;
    lock.unlock();
    std::exception_ptr error;
    try {
      task(device);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    errors_[device] = error;
    if (--running_ == 0) finished_.notify_one();
  }
}

}  // namespace candela
