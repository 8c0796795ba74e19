// libFuzzer target (issue 5): mutated STEP and BREP bytes through the reader and the pipeline, as the CLI
// takes them. The first byte picks the format (even: STEP, odd: BREP), the rest is the file. Every input
// must end in a mesh or a hexlayer::Error (exit codes 2-6), never a crash, a sanitizer report or a hang.
// Built by scripts/fuzz.sh (clang, -DHEXLAYER_FUZZ=ON); the seeds are in tests/fuzz/corpus.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "geometry/cad_solid.hpp"
#include "pipeline/pipeline.hpp"

namespace {

// A file of the fuzzer's bytes with the extension that picks the reader, removed afterwards.
class FuzzFile {
 public:
  FuzzFile(const uint8_t* data, size_t size, const char* extension)
      : path_("/tmp/hexlayer-fuzz-" + std::to_string(getpid()) + extension) {
    std::ofstream(path_, std::ios::binary)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  ~FuzzFile() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

void meshEverySolid(const std::string& path) {
  hexlayer::MeshOptions options;
  options.force = true;  // the mesh of a damaged part may fail validation: that is an answer, not a bug
  options.layers = 1;
  options.size = 10;  // a few dozen quads on the 60 x 40 mm seeds: many runs a minute under the sanitizers
  for (const TopoDS_Solid& solid : hexlayer::readSolids(path)) hexlayer::meshSolid(solid, options);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const bool brep = data[0] % 2 == 1;
  const FuzzFile file(data + 1, size - 1, brep ? ".brep" : ".step");
  try {
    // The readers run in the CLI's child process: OpenCASCADE's own crashes and hangs on damaged files
    // (a STEP reader SEGV found here: tests/fuzz/findings) are input errors there, and the fuzzer goes on
    // to what the pipeline makes of every shape that reads.
    meshEverySolid(file.path());
  } catch (const hexlayer::Error&) {
  }
  return 0;
}
