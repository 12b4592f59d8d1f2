#pragma once
// One thread that runs one call at a time beside the caller: start(f), then result() waits for
// f's value (or rethrows what it threw). The same thread serves every call, so a grid of many
// batches starts one thread, not one per batch (a thread's start costs its stack's page faults
// and TBB's attachment of a new external thread, each batch).
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace penumbra {

template <typename Value>
class BackgroundCall {
 public:
  BackgroundCall() : thread_([this] { serve(); }) {}
  BackgroundCall(const BackgroundCall&) = delete;
  BackgroundCall& operator=(const BackgroundCall&) = delete;
  ~BackgroundCall() {
    {
      const std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    changed_.notify_all();
    thread_.join();
  }

  // Starts `call` on the thread; the previous call's result must have been taken.
  void start(std::function<Value()> call) {
    {
      const std::lock_guard lock(mutex_);
      call_ = std::move(call);
    }
    changed_.notify_all();
  }

  // Waits for the call started last and returns its value, or rethrows its exception.
  Value result() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return value_.has_value() || error_ != nullptr; });
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
    Value value = std::move(*value_);
    value_.reset();
    return value;
  }

 private:
  void serve() {
    std::unique_lock lock(mutex_);
    for (;;) {
      changed_.wait(lock, [&] { return call_ != nullptr || stopping_; });
      if (!call_) return;
      std::function<Value()> call = std::move(call_);
      call_ = nullptr;
      lock.unlock();
      std::optional<Value> value;
      std::exception_ptr error;
      try {
        value.emplace(call());
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      value_ = std::move(value);
      error_ = error;
      changed_.notify_all();
    }
  }

  std::mutex mutex_;
  std::condition_variable changed_;
  std::function<Value()> call_;
  std::optional<Value> value_;
  std::exception_ptr error_;
  bool stopping_ = false;
  std::thread thread_;  // last: started once the members it reads exist
};

}  // namespace penumbra
