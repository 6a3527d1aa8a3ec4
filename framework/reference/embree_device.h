#pragma once
// The Embree device of the reference path tracer, with its instruction set and ray packet width
// chosen explicitly and checked, so that every x86-64 instruction set Embree supports can be
// selected (and tested) on any machine that has it.
//
// Instruction sets, narrowest first: "sse4.2", "avx", "avx2", "avx512" (Embree's AVX-512 kernels
// need the Skylake-server subset: F, CD, DQ, BW, VL). "auto" is the widest this CPU has. Embree
// silently falls back to SSE2 on a name it does not know, so names are checked here, and a set
// this CPU lacks is refused rather than left to fault.
//
// Packet width: how many rays one Embree query takes (1, 4, 8 or 16). 0 picks the widest width
// the chosen instruction set traces natively (16 with AVX-512, 8 with AVX and AVX2, 4 with
// SSE4.2). A wider width than native still works (Embree splits it), only slower.

#include <memory>
#include <string>
#include <vector>

#include <embree3/rtcore.h>

namespace lpvlab {

// The instruction sets lpvlab can ask Embree for, narrowest first (without "auto").
const std::vector<std::string>& embreeInstructionSets();
// Those of embreeInstructionSets() this CPU can run.
std::vector<std::string> supportedInstructionSets();
// The packet widths a query may use; 0 is "native".
const std::vector<int>& rayPacketWidths();

// Why `isa` ("auto" or a name) cannot be used on this CPU, or "" when it can: "instruction set
// 'avx9' is not one of auto, sse4.2, ..." or "this CPU lacks instruction set 'avx512' (it has ...)".
std::string instructionSetProblem(const std::string& isa);
// Why `width` is not a query width, or "".
std::string packetWidthProblem(int width);

struct RayEngineSettings {
  std::string isa = "auto";  // one of embreeInstructionSets() or "auto"
  int packetWidth = 0;       // one of rayPacketWidths()
};

struct ReleaseEmbreeDevice {
  void operator()(RTCDevice device) const { rtcReleaseDevice(device); }
};
using EmbreeDevicePtr = std::unique_ptr<RTCDeviceTy, ReleaseEmbreeDevice>;

// A device limited to one instruction set, and the packet width its queries use.
struct EmbreeDevice {
  EmbreeDevicePtr device;
  std::string isa;  // the instruction set in use ("auto" resolved)
  int packetWidth;  // 1, 4, 8 or 16 (0 resolved)
};

// Throws an Error with instructionSetProblem / packetWidthProblem when either is not "".
EmbreeDevice makeEmbreeDevice(const RayEngineSettings& settings);

}  // namespace lpvlab
