#pragma once
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace candela {

// One host thread per device of a backend that drives several, kept for the backend's life, so that every
// device's work is issued at once and each thread keeps its own current CUDA device. run(task) calls task(i)
// for every device i concurrently, device 0's on the calling thread, and returns when all have returned.
class DeviceThreads {
 public:
  explicit DeviceThreads(size_t devices);
  ~DeviceThreads();
  DeviceThreads(const DeviceThreads&) = delete;
  DeviceThreads& operator=(const DeviceThreads&) = delete;

  size_t size() const { return workers_.size() + 1; }
  // Rethrows the exception of the lowest device index that threw, after all have returned. Not reentrant: one
  // run at a time.
  void run(const std::function<void(size_t)>& task);

 private:
  void serve(size_t device);

  std::mutex mutex_;
  std::condition_variable wake_, finished_;
  const std::function<void(size_t)>* task_ = nullptr;
  uint64_t round_ = 0;  // counts runs: a worker runs the task once per round
  size_t running_ = 0;  // workers still running this round's task
  bool stopping_ = false;
  std::vector<std::exception_ptr> errors_;
  std::vector<std::thread> workers_;  // devices 1, 2, ...
};

}  // namespace candela
