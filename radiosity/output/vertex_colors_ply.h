#pragma once

#include <array>
#include <ostream>
#include <vector>

#include "meshing/patch_mesh.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/core/rgb.h"
#include "radiosity/output/tone_map.h"

namespace rad {

// Outgoing radiance L = B/π (W·m⁻²·sr⁻¹) at each output vertex of `interpolation`: the
// area-weighted mean of the radiosity of the elements around it (see VertexInterpolation).
// `radiosityPerElement` has one entry per element of the mesh the interpolation was built from.
std::vector<Rgb> interpolateVertexRadiance(const VertexInterpolation& interpolation,
                                           const std::vector<Rgb>& radiosityPerElement);
// The same from B at each element's 3 receiver points (Gauss points; SolveResult's
// pointRadiosity): each element's linear field through them, evaluated at its corners and
// averaged per output vertex (VertexInterpolation::interpolateCorners), clamped at zero where
// the extrapolation overshoots past a shadow edge. Falls back to the element means when
// `radiosityAtPoints` is empty.
std::vector<Rgb> interpolateVertexRadiance(
    const VertexInterpolation& interpolation, const std::vector<Rgb>& radiosityPerElement,
    const std::vector<std::array<Rgb, 3>>& radiosityAtPoints);

// Writes the solution as baked vertex colours: a binary_little_endian PLY 1.0 that MeshLab and
// Blender read. Per vertex: float x y z, float nx ny nz, float radiance_r radiance_g radiance_b
// (linear outgoing radiance, W·m⁻²·sr⁻¹) and uchar red green blue (the radiance through
// `toneMap`, sRGB). One triangle per element, with int indices into the output vertices; header
// comments state the units and the exposure. Open `out` in binary mode (AtomicFile(path, true)).
// `radianceVertex` has one entry per output vertex (RAD_CHECK: CheckFailure otherwise).
void writeVertexColorsPly(std::ostream& out, const VertexInterpolation& interpolation,
                          const PatchMesh& mesh, const std::vector<Rgb>& radianceVertex,
                          const ToneMap& toneMap);

}  // namespace rad
