#pragma once

#include <cstdint>

#include "radiosity/pipeline/solve_options.h"
#include "radiosity/scene/scene.h"

namespace rad {

// Resource limits, decided before the work starts, so absurd options or scenes fail at once
// with a clear message instead of running out of memory hours later.
// × 64 for emitter rows stays below 2^30, the most rays one row can hold.
inline constexpr int kMaxRaysPerElement = (1 << 24) - 1;
inline constexpr double kMaxElements = 4e6;
inline constexpr double kMaxCoordinate = 1e15;
// Analytic form factors: the most shadow rays (elements × shooting patches × receiver points ×
// shadow rays) a solve may need in the worst case, about 17 minutes at the rate assumed for the
// estimate in the message (two cores do 5 to 20 million per second).
inline constexpr double kMaxAnalyticShadowRays = 1e10;
inline constexpr double kAssumedShadowRaysPerSecond = 1e7;

// Upper bound on the memory of the form-factor rows a run may store: hemisphere rows hold at
// most min(rays, elements) entries each; analytic rows (gathering matrix or patch shots) at
// most elements × shooters entries; about 12 bytes per entry (index and value), 24 for analytic
// rows that also keep the factor at each of 3 receiver points (receiverPoints 3).
uint64_t formFactorMemoryEstimate(FormFactorMethod method, int elements, int shooters, int rays,
                                  int receiverPoints = 1);
// MemAvailable from /proc/meminfo in bytes; 0 when unknown (the check is then skipped).
uint64_t availableMemoryBytes();
// Throws InputError naming the options to change when `needed` exceeds `available` (0: unknown).
void checkFormFactorMemory(uint64_t needed, uint64_t available, FormFactorMethod method);
// Throws InputError (naming the file) for scenes too large or too far out to solve: more
// polygons than the element limit, coordinates beyond kMaxCoordinate. (Faces of more than 255
// vertices are refused by the OBJ line check.)
void checkSceneLimits(const Scene& scene);

}  // namespace rad
