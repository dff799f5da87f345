#include "radiosity/render/exposure_weights.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "radiosity/render/camera.h"

namespace rad {

std::vector<double> exposureWeights(const Camera& camera, const RenderScene& scene) {
  const CameraRays rays(camera);
  std::vector<double> weights(static_cast<size_t>(camera.width) * camera.height, 0.0);
  tbb::parallel_for(0, camera.height, [&](int y) {
    for (int x = 0; x < camera.width; ++x) {
      Eigen::Vector3d origin, direction;
      rays.generate(x + 0.5, y + 0.5, 0.5, 0.5, origin, direction);
      const SurfaceHit hit = scene.intersect(origin, direction);
      const bool lit = hit.hit() && !(hit.material && hit.material->isEmitter());
      weights[static_cast<size_t>(y) * camera.width + x] = lit ? 1.0 : 0.0;
    }
  });
  if (std::none_of(weights.begin(), weights.end(), [](double w) { return w > 0; })) weights.clear();
  return weights;
}

}  // namespace rad
