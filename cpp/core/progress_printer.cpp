#include "core/progress_printer.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace hexlayer {
namespace {

constexpr int kBarWidth = 24;
constexpr const char* kClearLine = "\r\033[K";  // back to the line's start, erase it

const char* prefixOf(ProgressStyle style) { return style == ProgressStyle::Machine ? "@progress " : "hexlayer: "; }

}  // namespace

std::string statusLine(const std::string& stage, double done, double total, double seconds) {
  std::ostringstream s;
  s << stage;
  if (total > 0) {
    const double share = std::clamp(done / total, 0.0, 1.0);
    const int filled = static_cast<int>(std::lround(share * kBarWidth));
    s << " [" << std::string(filled, '#') << std::string(kBarWidth - filled, '.') << "] " << std::setw(3)
      << std::lround(100 * share) << " %";
  }
  s << "  " << std::fixed << std::setprecision(1) << seconds << " s";
  return s.str();
}

ProgressStyle progressStyleFor(bool machine, int fd) {
  if (machine) return ProgressStyle::Machine;
  const char* term = std::getenv("TERM");
  const bool dumb = term != nullptr && std::string(term) == "dumb";
  return isatty(fd) && !dumb ? ProgressStyle::Terminal : ProgressStyle::Plain;
}

ProgressPrinter::ProgressPrinter(std::ostream& out, ProgressStyle style, double interval, bool ticker)
    : out_(out), style_(style), interval_(interval) {
  if (ticker && style == ProgressStyle::Terminal && interval > 0) ticker_ = std::thread([this] { tickLoop(); });
}

ProgressPrinter::~ProgressPrinter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
  clearStatus();
  out_.flush();
}

void ProgressPrinter::show(const Progress& event) {
  std::lock_guard<std::mutex> lock(mutex_);
  switch (event.kind) {
    case Progress::Kind::Start:
      stage_ = event.stage, done_ = total_ = 0, started_ = Clock::now();
      if (style_ == ProgressStyle::Machine) out_ << "@running " << stage_ << std::endl;
      if (style_ == ProgressStyle::Terminal) drawStatus();
      return;
    case Progress::Kind::Advance:
      advance(event);
      return;
    case Progress::Kind::Finish:
      stage_.clear();
      finishLine(event.line());
      return;
    default:
      finishLine(event.line());
  }
}

void ProgressPrinter::tick() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (style_ == ProgressStyle::Terminal && !stage_.empty()) drawStatus();
}

void ProgressPrinter::advance(const Progress& event) {
  if (event.stage != stage_) stage_ = event.stage, started_ = Clock::now();
  done_ = event.done, total_ = event.total;
  if (!due()) return;
  if (style_ == ProgressStyle::Terminal) return drawStatus();
  drawn_ = Clock::now();
  if (style_ == ProgressStyle::Machine)
    out_ << "@running " << stage_ << " " << std::llround(done_) << " " << std::llround(total_) << std::endl;
  else
    out_ << prefixOf(style_) << event.line() << std::endl;
}

void ProgressPrinter::finishLine(const std::string& line) {
  clearStatus();
  out_ << prefixOf(style_) << line << std::endl;
  if (style_ == ProgressStyle::Terminal && !stage_.empty()) drawStatus();  // a note while a stage runs
}

void ProgressPrinter::drawStatus() {
  drawn_ = Clock::now();
  const double seconds = std::chrono::duration<double>(drawn_ - started_).count();
  out_ << kClearLine << prefixOf(style_) << statusLine(stage_, done_, total_, seconds) << std::flush;
  statusShown_ = true;
}

void ProgressPrinter::clearStatus() {
  if (!statusShown_) return;
  out_ << kClearLine;
  statusShown_ = false;
}

bool ProgressPrinter::due() const {
  return interval_ <= 0 || std::chrono::duration<double>(Clock::now() - drawn_).count() >= interval_;
}

void ProgressPrinter::tickLoop() {
  std::unique_lock<std::mutex> lock(mutex_);
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(interval_));
  while (!wake_.wait_for(lock, period, [this] { return stop_; }))
    if (!stage_.empty()) drawStatus();
}

}  // namespace hexlayer
