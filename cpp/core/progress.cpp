#include "core/progress.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/error.hpp"

namespace hexlayer {

std::string Progress::line() const {
  std::ostringstream s;
  switch (kind) {
    case Kind::Start:
      return stage;
    case Kind::Advance:
      s << stage << ": " << std::llround(done) << "/" << std::llround(total);
      return s.str();
    case Kind::Finish:
      s << stage << ": " << std::fixed << std::setprecision(2) << seconds << " s";
      return s.str();
    default:
      return stage.empty() ? note : stage + ": " + note;
  }
}

Progress progressStart(const std::string& stage) {
  Progress p;
  p.kind = Progress::Kind::Start, p.stage = stage;
  return p;
}

Progress progressAdvance(const std::string& stage, double done, double total) {
  Progress p;
  p.kind = Progress::Kind::Advance, p.stage = stage, p.done = done, p.total = total;
  return p;
}

Progress progressNote(const std::string& stage, const std::string& note) {
  Progress p;
  p.kind = Progress::Kind::Note, p.stage = stage, p.note = note;
  return p;
}

Progress progressFinish(const std::string& stage, double seconds) {
  Progress p;
  p.kind = Progress::Kind::Finish, p.stage = stage, p.seconds = seconds;
  return p;
}

void reportProgress(const ProgressCallback& progress, const Progress& event) {
  if (progress) progress(event);
}

ProgressCallback ProgressRelay::callback() {
  return [this](const Progress& event) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (stopped_) throw internalError("stopped: the work beside it failed");
    queue_.push_back(event);
    changed_.notify_one();
  };
}

void ProgressRelay::close() {
  const std::lock_guard<std::mutex> lock(mutex_);
  closed_ = true;
  changed_.notify_one();
}

void ProgressRelay::stop() {
  const std::lock_guard<std::mutex> lock(mutex_);
  stopped_ = true;
}

void ProgressRelay::forward(bool untilClosed) {
  for (;;) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (untilClosed) changed_.wait(lock, [&] { return closed_ || !queue_.empty(); });
    if (queue_.empty()) return;  // every event so far handed on (closed, if untilClosed)
    const Progress event = std::move(queue_.front());
    queue_.pop_front();
    lock.unlock();
    try {
      reportProgress(progress_, event);
    } catch (...) {
      stop();
      throw;
    }
  }
}

}  // namespace hexlayer
