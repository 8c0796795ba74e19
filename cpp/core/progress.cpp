#include "core/progress.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

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

}  // namespace hexlayer
