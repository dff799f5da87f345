#pragma once

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstddef>
#include <vector>

#include "radiosity/output/tone_map.h"
#include "radiosity/render/light_probes.h"

namespace rad {

// Light probes (solve --probes) as the viewer draws them: each probe a sphere whose surface at
// the unit normal n shows what a white diffuse ball there would: radiance probeIrradiance(n)/π,
// tone-mapped to sRGB by the solution's own ToneMap, so a probe reads against the walls around
// it. Probes flagged inside geometry are left out.
//
// One vtkPolyData for all the spheres: triangles over
//   points      at centre + radius × n
//   point data  "srgb" (3 × uint8, the active scalars: the tone-mapped colour at n),
//               "probe" (int, the probe's index in the list it was made from)
// A UV sphere of `segments` around the vertical (+y) axis and segments / 2 bands from pole to
// pole: 2 + segments × (segments / 2 − 1) points and 2 × segments × (segments / 2 − 1) triangles.
namespace probe_array {
inline constexpr const char* srgb = "srgb";
inline constexpr const char* probe = "probe";
}  // namespace probe_array

// The spheres' resolution for this many probes: 16 segments up to 10,000 probes, 8 up to
// 100,000, then 4 (an octahedron), so a dense grid stays a few million triangles.
int probeSphereSegments(std::size_t probes);

// 0.15 × the probes' spacing, the smallest gap between distinct coordinates along any axis
// (gaps below 1e-6 of the probes' extent count as equal): a probe grid's spacing, and never more
// than the distance between the two nearest probes, so spheres never overlap. `fallback` when the
// probes have no such gap (fewer than two, or all at one point).
double probeSphereRadius(const std::vector<ProbeSh>& probes, double fallback);

// The spheres of the probes not flagged inside; `segments` even and ≥ 4 (a bug otherwise:
// CheckFailure).
vtkSmartPointer<vtkPolyData> makeProbePolyData(const std::vector<ProbeSh>& probes, double radius,
                                               const ToneMap& toneMap, int segments);

}  // namespace rad
