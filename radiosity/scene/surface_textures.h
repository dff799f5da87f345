#pragma once

#include "meshing/patch_mesh.h"
#include "radiosity/core/rgb.h"
#include "radiosity/scene/scene.h"

namespace rad {

// A material's reflectance and emission with its textures applied, in one place for the solver
// and the renders: Kd × map_Kd (baseColorFactor × baseColorTexture) and Ke × map_Ke. Elements
// whose polygon has no texture coordinates, and materials without the map, get the factor alone.
// A reflectance is clamped to [0, 1] per channel (an HDR colour map could exceed 1).

// The area average over the element's UV footprint: the element's reflectance in the solve.
Rgb elementReflectance(const Scene& scene, const PatchMesh& mesh, int element);
// Emitted radiance (W·m⁻²·sr⁻¹) averaged over the element likewise.
Rgb elementEmission(const Scene& scene, const PatchMesh& mesh, int element);

// The bilinear texel at a point of the element given by its barycentrics (RayHit::u, v: point =
// (1-u-v)·c0 + u·c1 + v·c2 over PatchMesh::corners): the reflectance the renders see at a hit.
Rgb reflectanceAt(const Scene& scene, const PatchMesh& mesh, int element, double u, double v);
Rgb emissionAt(const Scene& scene, const PatchMesh& mesh, int element, double u, double v);

// Whether the element's reflectance varies inside it (a colour map and texture coordinates):
// then reflectanceAt differs from elementReflectance and the outputs show the texel.
bool hasReflectanceTexture(const Scene& scene, const PatchMesh& mesh, int element);

// The albedo-free light that reached a surface of reflectance ρ from what leaves it and what it
// emits, (outgoing − emitted)/ρ per channel: the irradiance H from radiosities, H/π from
// radiances. It is what varies smoothly across elements of different reflectance, so the
// outputs interpolate it and multiply by the texel's ρ: L = Le + ρ(texel)·H/π. 0 in a channel
// where ρ = 0 (there B = E: the solution keeps no record of the light arriving).
Rgb incidentLight(const Rgb& outgoing, const Rgb& emitted, const Rgb& rho);

}  // namespace rad
