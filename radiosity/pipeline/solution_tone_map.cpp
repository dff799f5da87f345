#include "radiosity/pipeline/solution_tone_map.h"

#include "radiosity/output/display_radiance.h"

namespace rad {

ToneMap solutionToneMap(const Solution& solution) {
  std::vector<Rgb> emitted(solution.radiosity.size());
  for (size_t e = 0; e < emitted.size(); ++e)
    emitted[e] = solution.scene.materials[solution.mesh->material(static_cast<int>(e))].emission;
  return solutionToneMap(solution.radiosity, solution.problem.area, emitted);
}

}  // namespace rad
