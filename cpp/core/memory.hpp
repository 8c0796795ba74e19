// Memory: what the process has used, and what a mesh will need before it is made (the guard that refuses a
// size the machine cannot hold, instead of running out half way).
#pragma once

namespace hexlayer {

// The process's peak resident memory so far, in MiB (Linux's ru_maxrss, in KiB).
double peakMemoryMiB();

// The machine's physical memory, in bytes.
double machineBytes();

struct MemoryEstimate {
  double quads = 0, hexes = 0, bytes = 0;
  double machineBytes = 0;
  bool fits() const { return bytes <= machineBytes; }
};

// [in] wallArea: area of one wall (the top) to be covered by quads of edge `size` (same units); [in] layers, order
// (1: 8-node, 2: 20-node hexes); [in] machine: bytes available. Hexes = wallArea / size^2 x layers, each
// kBytesPerHex (the peak per hex measured on plate.step at size 0.3: 73.5 MB for 64 312 hexes, x 2 for safety),
// twice that for 20-node hexes.
MemoryEstimate estimateMemory(double wallArea, double size, int layers, int order, double machine);

// The same from the number of quads made (adaptive sizes run down to --min-size: the wall's area over the size
// squared under-counts them). [in] quads: of the chordal surface; [in] layers, order, machine: as estimateMemory.
MemoryEstimate estimateMemoryOfQuads(double quads, int layers, int order, double machine);

}  // namespace hexlayer
