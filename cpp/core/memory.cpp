#include "core/memory.hpp"

#include <sys/resource.h>
#include <unistd.h>

namespace hexlayer {
namespace {

constexpr double kBytesPerHex = 2000;

}  // namespace

double peakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

double machineBytes() {
  return static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
}

MemoryEstimate estimateMemory(double wallArea, double size, int layers, int order, double machine) {
  return estimateMemoryOfQuads(wallArea / (size * size), layers, order, machine);
}

MemoryEstimate estimateMemoryOfQuads(double quads, int layers, int order, double machine) {
  MemoryEstimate e;
  e.quads = quads;
  e.hexes = e.quads * layers;
  e.bytes = e.hexes * kBytesPerHex * (order == 2 ? 2 : 1);
  e.machineBytes = machine;
  return e;
}

}  // namespace hexlayer
