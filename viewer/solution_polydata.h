#pragma once

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/core/rgb.h"
#include "radiosity/output/tone_map.h"

namespace rad {

// A radiosity solution as VTK PolyData, the layout of solution.vtp. One triangle per element,
// in element order, over the vertices of VertexInterpolation (split where the material changes
// or the surface creases, so smooth colours keep corners sharp). Arrays:
//   cell data  "B" (3 × double, W/m²), "radiance" (3 × double, B/π, W·m⁻²·sr⁻¹),
//              "unshot" (3 × double, W), "area" (double), "patch", "material", "level" (int),
//              "srgb" (3 × uint8, the tone-mapped colour of the images and vertex_colors.ply)
//   point data "radiance" (3 × double, area-weighted mean of the elements at the vertex), "srgb"
//   field data "exposure" (the tone map's exposure)
namespace solution_array {
inline constexpr const char* radiosity = "B";
inline constexpr const char* radiance = "radiance";
inline constexpr const char* unshot = "unshot";
inline constexpr const char* area = "area";
inline constexpr const char* patch = "patch";
inline constexpr const char* material = "material";
inline constexpr const char* level = "level";
inline constexpr const char* srgb = "srgb";
inline constexpr const char* exposure = "exposure";
}  // namespace solution_array

// `unshot` may be empty (zeros). A size mismatch is a bug (RAD_CHECK: CheckFailure).
vtkSmartPointer<vtkPolyData> makeSolutionPolyData(const PatchMesh& mesh,
                                                  const std::vector<Rgb>& radiosity,
                                                  const std::vector<Rgb>& unshot,
                                                  const ToneMap& toneMap);

// Rewrites B, radiance, unshot, srgb (cells and points) and the exposure of a solution PolyData
// in place, e.g. after a solver step. Point values are the area-weighted means over the cells
// that use the point, as in vertex_colors.ply.
void setSolutionArrays(vtkPolyData* data, const std::vector<Rgb>& radiosity,
                       const std::vector<Rgb>& unshot, const ToneMap& toneMap);

// Area-weighted mean of per-cell values at each point (the same weights as VertexInterpolation).
std::vector<double> pointAverages(vtkPolyData* data, const std::vector<double>& cellValues);

// The tone map the solution was shown with (field data), or autoExposure over the cell radiance.
ToneMap solutionToneMap(vtkPolyData* data);

}  // namespace rad
