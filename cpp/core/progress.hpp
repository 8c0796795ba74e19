// Progress of a run as its stages report it: a stage starts, may say how far it is (done of total) or note
// something (a failed try), and finishes in so many seconds. One callback takes every event: the CLI draws
// the running stage from it (a bar on a terminal, plain lines otherwise), `--machine` hands it to the FreeCAD
// workbench's progress bar, the Python module passes the lines on.
#pragma once
#include <functional>
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

}  // namespace hexlayer
