#include "radiosity/pipeline/resource_limits.h"

#include <algorithm>
#include <fstream>
#include <string>

#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"

namespace rad {
uint64_t formFactorMemoryEstimate(FormFactorMethod method, int elements, int shooters, int rays,
                                  int receiverPoints) {
  constexpr uint64_t kBytesPerEntry = 12;   // 4-byte column index + 8-byte value
  constexpr uint64_t kBytesPerPoints = 12;  // 3 single-precision point factors
  const uint64_t n = static_cast<uint64_t>(std::max(elements, 0));
  if (method == FormFactorMethod::Analytic)
    return n * static_cast<uint64_t>(std::max(shooters, 0)) *
           (kBytesPerEntry + (receiverPoints == 3 ? kBytesPerPoints : 0));
  return n * std::min<uint64_t>(static_cast<uint64_t>(std::max(rays, 0)), n) * kBytesPerEntry;
}

uint64_t availableMemoryBytes() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  uint64_t value = 0;
  while (in >> key >> value >> unit)
    if (key == "MemAvailable:") return value * 1024;  // reported in kB
  return 0;
}

void checkFormFactorMemory(uint64_t needed, uint64_t available, FormFactorMethod method) {
  if (available == 0 || needed <= available) return;
  const auto gib = [](uint64_t bytes) { return formatNumber(bytes / double(1ull << 30)) + " GiB"; };
  throw InputError(
      "the form-factor rows may need up to " + gib(needed) + " but only " + gib(available) +
      " of memory is available: " +
      (method == FormFactorMethod::Analytic
           ? "raise --patch-area (fewer shooting patches) or --max-area (fewer elements), "
             "or lower --elements"
           : "lower --elements or raise --max-area (fewer elements), or lower --rays"));
}

void checkSceneLimits(const Scene& scene) {
  if (scene.polygons.size() > kMaxElements)
    throw InputError(scene.sourcePath, 0,
                     std::to_string(scene.polygons.size()) +
                         " polygons, more than the element limit " + formatNumber(kMaxElements) +
                         ": every polygon needs at least one element");
  // Beyond this, double precision leaves less than a millimetre-per-kilometre of resolution and
  // Embree's single-precision BVH cannot separate nearby surfaces.
  for (std::size_t i = 0; i < scene.positions.size(); ++i)
    if (!scene.positions[i].allFinite() ||
        !(scene.positions[i].cwiseAbs().maxCoeff() <= kMaxCoordinate))
      throw InputError(scene.sourcePath, 0,
                       "vertex " + std::to_string(i + 1) + " has a coordinate beyond " +
                           formatNumber(kMaxCoordinate) + " scene units: rescale the scene");
}

}  // namespace rad
