#include "radiosity/bake/lightmap_pages.h"

#include "radiosity/core/check.h"
#include "radiosity/render/radiosity_integrator.h"

namespace rad {

LightmapPages::LightmapPages(const Solution& solution, const LightmapLayout& layout,
                             const VertexInterpolation& interpolation,
                             const ElementExposure& exposure, const BakeSpec& spec, BakeRays& rays)
    : solution_(solution),
      layout_(layout),
      interpolation_(interpolation),
      exposure_(exposure),
      spec_(spec) {
  // --gather N, or --gather 0 --light-rays N: the direct light per texel by shadow rays, the rest
  // gathered from the solution (final_gather.h) or its indirect part interpolated
  // (direct_indirect_split.h).
  if (spec.gather.castsRays()) {
    gatherPass_ = makeRadiosityIntegrator(rays.view(), solution.radiosity,
                                          solution.directIrradiance, spec.gather);
    gather_ = dynamic_cast<const TexelRadiance*>(gatherPass_.get());
    RAD_CHECK(gather_ != nullptr);
    gatherError_.assign(layout.pages,
                        std::vector<Rgb>(static_cast<size_t>(layout.width) * layout.height));
  }
}

std::vector<Lightmap> LightmapPages::bake(const TexelSolution& values,
                                          const std::vector<Lightmap>* shape) {
  const PatchMesh& mesh = *solution_.mesh;
  std::vector<Lightmap> pages;
  if (gather_) {
    const GatheredTexels gathered(solution_, *gather_, layout_, spec_.content, spec_.seed);
    for (int page = 0; page < layout_.pages; ++page)
      pages.push_back(bakeLightmap(
          mesh, layout_, interpolation_, values.vertexValues, spec_.dilation,
          [&](int e, const Eigen::Vector3d& b, size_t texel) {
            Rgb standardError;
            const Rgb value = gathered(page, e, b, texel, standardError);
            gatherError_[page][texel] = standardError;
            return value;
          },
          page));
    return pages;
  }
  const InterpolatedTexels interpolated(solution_, interpolation_, exposure_, spec_.content,
                                        values);
  const TexelEvaluator evaluate = [&](int e, const Eigen::Vector3d& b, size_t) {
    return interpolated(e, b);
  };
  for (int page = 0; page < layout_.pages; ++page)
    pages.push_back(shape ? bakeOnTexels((*shape)[page], layout_, evaluate)
                          : bakeLightmap(mesh, layout_, interpolation_, values.vertexValues,
                                         spec_.dilation, evaluate, page));
  return pages;
}

}  // namespace rad
