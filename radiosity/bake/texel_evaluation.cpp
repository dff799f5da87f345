#include "radiosity/bake/texel_evaluation.h"

#include <cmath>

#include "radiosity/core/rng.h"
#include "radiosity/core/stream_tags.h"
#include "radiosity/output/vertex_colors_ply.h"
#include "radiosity/render/sobol_sampler.h"
#include "radiosity/render/texel_footprint.h"
#include "radiosity/scene/surface_textures.h"

namespace rad {

bool texelsFromIncidentLight(const Scene& scene, LightmapContent content) {
  return content == LightmapContent::Irradiance || !scene.textures.empty();
}

InterpolatedTexels::InterpolatedTexels(const Solution& solution,
                                       const VertexInterpolation& interpolation,
                                       const ElementExposure& exposure, LightmapContent content,
                                       const TexelSolution& values)
    : scene_(solution.scene),
      mesh_(*solution.mesh),
      interpolation_(interpolation),
      exposure_(exposure),
      vertexValues_(values.vertexValues),
      emission_(values.emission),
      irradiance_(content == LightmapContent::Irradiance),
      textured_(texelsFromIncidentLight(solution.scene, content)) {
  if (!textured_) return;
  const std::vector<Rgb>& rho = solution.problem.reflectance;
  std::vector<Rgb> incident(mesh_.elementCount());
  for (int e = 0; e < mesh_.elementCount(); ++e)
    incident[e] = incidentLight(values.radiosity[e], M_PI * emission_[e], rho[e]);
  vertexIncident_ = interpolateVertexRadiance(interpolation_, incident);
}

Rgb InterpolatedTexels::operator()(int e, const Eigen::Vector3d& b) const {
  if (exposure_.buriedAtBarycentric(e, b[1], b[2])) return irradiance_ ? Rgb() : emission_[e];
  const auto& v = interpolation_.triangle(e);
  auto at = [&](const std::vector<Rgb>& perVertex) {
    return perVertex[v[0]] * b[0] + perVertex[v[1]] * b[1] + perVertex[v[2]] * b[2];
  };
  if (irradiance_) return at(vertexIncident_);
  if (!textured_ || !hasReflectanceTexture(scene_, mesh_, e)) return at(vertexValues_);
  return emission_[e] + reflectanceAt(scene_, mesh_, e, b[1], b[2]) * at(vertexIncident_);
}

GatheredTexels::GatheredTexels(const Solution& solution, const TexelRadiance& gather,
                               const LightmapLayout& layout, LightmapContent content, uint64_t seed)
    : scene_(solution.scene),
      mesh_(*solution.mesh),
      gather_(gather),
      layout_(layout),
      irradiance_(content == LightmapContent::Irradiance),
      seed_(seed) {}

Rgb GatheredTexels::operator()(int page, int e, const Eigen::Vector3d& b, size_t texel,
                               Rgb& standardError) const {
  const uint64_t key = streamKey(seed_, stream_tag::kLightmapTexel + page, texel);  // per texel
  Rng rng(key);
  SobolSampler sampler(seed_, key, rng);
  sampler.startSample(0);
  RayCounts counts;
  const TexelFootprint footprint = TexelFootprint::of(layout_.texels[e], b);
  const Rgb out = gather_.outgoingRadiance(e, footprint, sampler, counts, standardError);
  // Gathered at the texel with its own ρ: divide that one out.
  const Rgb& texelLe = scene_.materials[mesh_.material(e)].emission;
  return irradiance_ ? incidentLight(out, texelLe, reflectanceAt(scene_, mesh_, e, b[1], b[2]))
                     : out;
}

}  // namespace rad
