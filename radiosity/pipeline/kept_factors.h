#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/formfactors/form_factor_row.h"
#include "radiosity/formfactors/shot_rows.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/scene/scene.h"

namespace rad {

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
  std::vector<FormFactorRow> rows;                // per element: its hemisphere row
};

inline constexpr const char* kKeptFactorsFile = "factors.bin";

// Hash of what the kept factors depend on: the geometry (positions, polygons and their texture
// coordinates), what makes a surface stop or bend rays (specular kind and values, cut-out masks,
// two-sidedness), and the mesh and ray options. Not the materials' diffuse and emission factors,
// nor the lights (their first shot is kept, E_d per light): those are what relight changes.
std::string keptFactorsFingerprint(const Scene& scene, const SolveOptions& options);

// factors.bin: the line "radiosity kept factors 1", a u64 (little-endian) byte count and that
// many bytes of JSON (scene, fingerprint, elements, lights, options), then little-endian arrays:
// area (f64 × n); per light, E_d (f64 × 3n); per element its row: u32 count c, u8 tinted, f64
// escaped, i32 targets[c], f32 values[c], and f32 × 3c tinted values when tinted.
void writeKeptFactors(std::ostream& out, const KeptFactors& kept);
// InputError naming the file (and the row or array) when it is not such a file, is cut short or
// holds values no solve writes (targets out of range, negative or non-finite factors).
KeptFactors readKeptFactors(const std::string& path);

// The kept rows as progressive shooting reads them (elements shoot their own rows).
class KeptRows : public ShotRows {
 public:
  explicit KeptRows(const KeptFactors& kept) : kept_(kept) {}
  int shooterCount() const override { return static_cast<int>(kept_.rows.size()); }
  int shooterOf(int element) const override { return element; }
  double shooterArea(int shooter) const override { return kept_.area[shooter]; }
  const FormFactorRow& powerFractions(int shooter) override { return kept_.rows[shooter]; }
  std::string description() const override { return "kept element rows (hemisphere)"; }

 private:
  const KeptFactors& kept_;
};

}  // namespace rad
