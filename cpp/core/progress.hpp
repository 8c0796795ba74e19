// Progress of a run as its stages report it: a stage starts, may say how far it is (done of total) or note
// something (a failed try), and finishes in so many seconds. One callback takes every event: the CLI draws
// the running stage from it (a bar on a terminal, plain lines otherwise), `--machine` hands it to the FreeCAD
// workbench's progress bar, the Python module passes the lines on.
#pragma once
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <string>

namespace hexlayer {

struct Progress {
  enum class Kind { Start, Advance, Note, Finish };
  Kind kind = Kind::Note;
  std::string stage;           // the stage's report key ("quad_mesh"); empty for a note about the run
  double done = 0, total = 0;  // Advance: how far the stage is (0 <= done <= total, total > 0)
  double seconds = 0;          // Finish: the stage's wall time
  std::string note;            // Note: the message

  // The event as one line: "quad_mesh: 1.23 s" (Finish), "quad_mesh: 3/13" (Advance), "quad_mesh: <note>"
  // (Note; the note alone without a stage), "quad_mesh" (Start).
  std::string line() const;
  // Whether the event is one of the lines a log keeps (Finish, Note), not a running stage's state.
  bool isLine() const { return kind == Kind::Finish || kind == Kind::Note; }
};

using ProgressCallback = std::function<void(const Progress&)>;

// The event constructors. [in] stage: the report key; [in] done, total: how far; [in] seconds: wall time;
// [in] note: the message. Returns the event.
Progress progressStart(const std::string& stage);
Progress progressAdvance(const std::string& stage, double done, double total);
Progress progressNote(const std::string& stage, const std::string& note);
Progress progressFinish(const std::string& stage, double seconds);

// Calls progress(event) if progress is set. [in] progress: may be empty; [in] event.
void reportProgress(const ProgressCallback& progress, const Progress& event);

// The events of work running on a thread of its own, handed to a callback on the thread that waits for it: a callback
// is called on one thread only (the Python module's takes the GIL), the events in their order.
class ProgressRelay {
 public:
  // [in] progress: the waiting thread's callback (may be empty).
  explicit ProgressRelay(ProgressCallback progress) : progress_(std::move(progress)) {}
  // The callback the work reports through: its events are queued; once stop() was called it throws instead, which
  // ends the work at its next event.
  ProgressCallback callback();
  // The work is done, whichever way it ended (called on its thread).
  void close();
  // The work is no longer wanted.
  void stop();
  // On the waiting thread: hands on the events queued so far, or (untilClosed) those and the ones to come until
  // close(). An exception of the callback stops the work (stop()) and leaves this function. [in] untilClosed.
  void forward(bool untilClosed);

 private:
  ProgressCallback progress_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Progress> queue_;
  bool closed_ = false, stopped_ = false;
};

}  // namespace hexlayer
