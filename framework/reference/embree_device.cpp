#include "framework/reference/embree_device.h"

#include <algorithm>

#include "framework/core/cpu_features.h"
#include "framework/core/error.h"

namespace lpvlab {

namespace {

bool cpuHas(const std::string& isa) {
  if (isa == "sse4.2") return cpuHasSse42();
  if (isa == "avx") return cpuHasAvx();
  if (isa == "avx2") return cpuHasX86_64_v3();
  if (isa == "avx512") return cpuHasX86_64_v4();
  return false;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

int nativeWidth(RTCDevice device) {
  if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED)) return 16;
  if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED)) return 8;
  if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED)) return 4;
  return 1;
}

}  // namespace

const std::vector<std::string>& embreeInstructionSets() {
  static const std::vector<std::string> sets = {"sse4.2", "avx", "avx2", "avx512"};
  return sets;
}

std::vector<std::string> supportedInstructionSets() {
  return namesThisCpuRuns(embreeInstructionSets(), cpuHas);
}

const std::vector<int>& rayPacketWidths() {
  static const std::vector<int> widths = {0, 1, 4, 8, 16};
  return widths;
}

std::string instructionSetProblem(const std::string& isa) {
  const std::vector<std::string>& known = embreeInstructionSets();
  if (isa != "auto" && std::find(known.begin(), known.end(), isa) == known.end())
    return "instruction set '" + isa + "' is not one of auto, " + joined(known);
  const std::vector<std::string> supported = supportedInstructionSets();
  if (supported.empty()) return "this CPU lacks SSE4.2, the narrowest instruction set lpvlab traces with";
  if (isa != "auto" && std::find(supported.begin(), supported.end(), isa) == supported.end())
    return "this CPU lacks instruction set '" + isa + "' (it has " + joined(supported) + ")";
  return {};
}

std::string packetWidthProblem(int width) {
  const std::vector<int>& widths = rayPacketWidths();
  if (std::find(widths.begin(), widths.end(), width) != widths.end()) return {};
  return "packet width " + std::to_string(width) + " is not one of 0 (native), 1, 4, 8, 16";
}

EmbreeDevice makeEmbreeDevice(const RayEngineSettings& settings) {
  for (const std::string& problem :
       {instructionSetProblem(settings.isa), packetWidthProblem(settings.packetWidth)})
    if (!problem.empty()) throw Error("path tracer: " + problem);
  const std::string isa = settings.isa == "auto" ? supportedInstructionSets().back() : settings.isa;

  // "isa=" pins Embree to exactly this set, the same whichever CPU runs it.
  EmbreeDevicePtr device(rtcNewDevice(("isa=" + isa).c_str()));
  if (!device) throw Error("path tracer: Embree could not create a device for '" + isa + "'");
  if (rtcGetDeviceError(device.get()) != RTC_ERROR_NONE)
    throw Error("path tracer: Embree refused instruction set '" + isa + "' (error " +
                std::to_string(int(rtcGetDeviceError(device.get()))) + ")");
  const int width = settings.packetWidth > 0 ? settings.packetWidth : nativeWidth(device.get());
  return {std::move(device), isa, width};
}

}  // namespace lpvlab
