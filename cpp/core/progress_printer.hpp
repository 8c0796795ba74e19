// Progress events (progress.hpp) shown to a person or handed to a program, on a stream (the CLI's stderr).
// - Terminal: finished stages and notes as lines, below them one status line redrawn in place: the running stage
//   with a bar and its percentage if it reports done/total, and the seconds it has run. Redrawn at most every
//   `interval` seconds, and by tick() (a ticker thread, so that a stage that reports nothing still shows time).
// - Plain (a file or a pipe): a line per finished stage and note ("hexlayer: quad_mesh: 1.23 s"), and the running
//   stage's done/total ("hexlayer: quad_mesh: 3/39") at most every `interval` seconds. No control characters.
// - Machine (the FreeCAD workbench): "@progress <line>" per finished stage and note, "@running <stage>" when a
//   stage starts and "@running <stage> <done> <total>" at most every `interval` seconds.
#pragma once
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <ostream>
#include <string>
#include <thread>

#include "core/progress.hpp"

namespace hexlayer {

enum class ProgressStyle { Terminal, Plain, Machine };

class ProgressPrinter {
 public:
  // [in,out] out: the stream written to (outlives the printer); [in] style; [in] interval: least seconds between
  // two drawings of the running stage (0: every event, for tests); [in] ticker: redraw a terminal's status line
  // from a thread of its own every `interval` (Terminal only, interval > 0).
  ProgressPrinter(std::ostream& out, ProgressStyle style, double interval, bool ticker);
  ~ProgressPrinter();  // stops the ticker and clears the status line
  ProgressPrinter(const ProgressPrinter&) = delete;
  ProgressPrinter& operator=(const ProgressPrinter&) = delete;

  // Shows one event. [in] event. Thread-safe.
  void show(const Progress& event);
  // Redraws the terminal's status line (the running stage's seconds go on). Thread-safe.
  void tick();

 private:
  using Clock = std::chrono::steady_clock;
  void finishLine(const std::string& line);  // a line that stays, above the status line
  void advance(const Progress& event);
  void drawStatus();
  void clearStatus();
  bool due() const;  // the running stage may be drawn again
  void tickLoop();

  std::ostream& out_;
  const ProgressStyle style_;
  const double interval_;
  std::mutex mutex_;
  std::string stage_;            // the running stage, empty between stages
  double done_ = 0, total_ = 0;  // its last done/total (total 0: none reported)
  Clock::time_point started_, drawn_;
  bool statusShown_ = false;  // a status line is on the terminal
  bool stop_ = false;
  std::condition_variable wake_;
  std::thread ticker_;
};

// The style for the CLI's stderr: Machine if asked, Terminal if fd is a terminal (and TERM is not "dumb"), else
// Plain. [in] machine: --machine; [in] fd: the file descriptor shown on. Returns the style.
ProgressStyle progressStyleFor(bool machine, int fd);

// The status line of a running stage: "quad_mesh [#######.............]  35 %  2.1 s", or "wall_sides  12.3 s"
// without done/total. [in] stage; [in] done, total; [in] seconds: how long it has run. Returns the line.
std::string statusLine(const std::string& stage, double done, double total, double seconds);

}  // namespace hexlayer
