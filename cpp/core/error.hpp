// Errors that end a run, each with the CLI exit code of the brief (0 done, 2 usage, 3 input, 4 geometry,
// 5 internal) and 6 for a mesh that failed its validation (README, "Exit codes").
#pragma once
#include <stdexcept>
#include <string>

namespace hexlayer {

enum class ExitCode : int {
  Ok = 0,
  BadUsage = 2,
  BadInput = 3,
  UnsupportedGeometry = 4,
  Internal = 5,
  InvalidMesh = 6
};

class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

// Bad option value or command line (exit 2).
inline Error usageError(const std::string& m) { return Error(ExitCode::BadUsage, m); }
// Missing, unreadable or invalid input file / solid (exit 3).
inline Error inputError(const std::string& m) { return Error(ExitCode::BadInput, m); }
// A valid solid this method does not handle: not thin, non-manifold chordal surface (exit 4).
inline Error geometryError(const std::string& m) { return Error(ExitCode::UnsupportedGeometry, m); }
// A step that should not fail did (a truncated result from a child process, data Gmsh left out) (exit 5).
inline Error internalError(const std::string& m) { return Error(ExitCode::Internal, m); }
// The finished mesh failed a validation check (inverted hex, not conformal, not watertight, volume);
// nothing was written (exit 6).
inline Error validationError(const std::string& m) { return Error(ExitCode::InvalidMesh, m); }

}  // namespace hexlayer
