#pragma once

#include <Eigen/Core>
#include <array>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/pipeline/kept_row_table.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/scene/lights.h"
#include "radiosity/scene/scene.h"

namespace rad {

// The file format of kept factors (factors.bin) and what it records; the solve's side of them
// (keepLightsApart, KeptRows) is in kept_factors_stage.h.
//
// What `solve --keep-factors` keeps beside its outputs (factors.bin) so that `relight` can solve
// the scene again with other material colours, emission or light strengths and cast no ray:
// everything that took rays. The radiosity system B = E + ρ F B depends on the materials and
// lights only through E and ρ; F (the rows), the exposed areas and each light's direct irradiance
// E_d depend on geometry alone.
struct KeptFactors {
  std::string scenePath;
  std::string fingerprint;                        // keptFactorsFingerprint of the scene and options
  SolveOptions options;                           // the solve's mesh, ray and solver options
  std::vector<double> area;                       // per element: its exposed area
  std::vector<std::string> lightGroups;           // per light: its group (light_groups.h)
  std::vector<std::string> lightTypes;            // per light: lightTypeName
  std::vector<std::vector<Rgb>> lightIrradiance;  // per light, per element: E_d (W·m⁻²)
  // A hash of the lights as solved (addLights): relight refuses lights that moved or changed
  // since, whose E_d the kept one no longer is. Empty in files kept before it was recorded.
  std::string lightsFingerprint;
  // Per material name: a hash of what decides which rays it stops (keptMaterialVisibility):
  // update refuses a material turned two-sided or given a cut-out, which changes rows without
  // moving geometry. Empty in files kept before it was recorded.
  std::map<std::string, std::string> materialVisibility;
  // A hash of what the materials give ρ and E from (keptMaterialsFingerprint): an update that
  // finds no edit returns the kept solution only when these are as solved. Empty in files kept
  // before it was recorded.
  std::string materialsFingerprint;
  KeptRowTable rows;  // per element: its hemisphere row

  // For `update` after a geometry edit (incremental.h): what the mesh was, to tell which elements
  // stayed put, and the inputs that must be the same again.
  double elementEdge = 0;  // the mesh's element size S (ElementSizing::edge): update meshes with it
  LightInput lightInput;   // the solve's --lights file and --sky/--sun shortcuts
  std::vector<std::array<Eigen::Vector3d, 3>> corners;  // per element
  std::vector<int> material;                            // per element
  std::vector<int> patch;                               // per element
  std::vector<int> rayMultiplier;                       // per element: its row's rays / --rays
};

inline constexpr const char* kKeptFactorsFile = "factors.bin";

// Hash of what the kept factors depend on: the geometry (positions, polygons and their texture
// coordinates), what makes a surface stop or bend rays (specular kind and values, cut-out masks,
// two-sidedness), and the mesh and ray options. Not the materials' diffuse and emission factors,
// nor the lights (their first shot is kept, E_d per light): those are what relight changes.
std::string keptFactorsFingerprint(const Scene& scene, const SolveOptions& options);
// Per material name, a hash of its kind, specular values, two-sidedness and cut-out mask: what
// decides which rays it stops or bends (KeptFactors::materialVisibility).
std::map<std::string, std::string> keptMaterialVisibility(const Scene& scene);
// Hash of the materials' diffuse and emission factors and textures (names, colours, texels): what
// the solve's ρ and E come from, and what relight changes (KeptFactors::materialsFingerprint).
std::string keptMaterialsFingerprint(const Scene& scene);
// The fingerprint of the lights a kept solve cast its first shot from (KeptFactors::
// lightsFingerprint): relight and update compare the scene's lights now against it.
std::string keptLightsFingerprint(const std::vector<Light>& lights);

// factors.bin: the line "radiosity kept factors 2", a u64 (little-endian) byte count and that
// many bytes of JSON (scene, fingerprint, elements, lights, options, element_edge, light_input,
// lights_fingerprint, material_visibility, materials_fingerprint),
// then little-endian arrays: area (f64 × n); per light, E_d (f64 × 3n); per element its row: u32
// count c, u8 tinted, f64 escaped, i32 targets[c], f32 values[c], and f32 × 3c tinted values when
// tinted; then the mesh: corners (f64 × 9n), material (i32 × n), patch (i32 × n), ray multiplier
// (u8 × n).
void writeKeptFactors(std::ostream& out, const KeptFactors& kept);
// InputError naming the file (and the row or array) when it is not such a file, is cut short or
// holds values no solve writes (targets out of range, negative or non-finite factors).
// KeptParts::Header reads only the header (scene, options, lights; no arrays): enough to load the
// scene while the rest is read.
enum class KeptParts { All, Header };
KeptFactors readKeptFactors(const std::string& path, KeptParts parts = KeptParts::All);

}  // namespace rad
